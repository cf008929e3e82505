a = Atan2(1);
