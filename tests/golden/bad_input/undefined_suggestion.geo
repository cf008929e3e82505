length = 2;
b = lenght * 2;
