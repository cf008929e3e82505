a = 1e;
