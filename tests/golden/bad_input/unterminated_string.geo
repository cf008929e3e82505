Printf("hello);
a = 1;
