x = 3;
Error("x is %g", x);
