a = Sinus(1);
