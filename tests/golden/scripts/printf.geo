// Expressions and Printf: what a script prints goes to standard output.
a = 3;
b = a * 2 + 1;   // 7
c = (a + b) / 4; // 2.5
d = 2 ^ 3 % 5;   // 8 % 5 = 3
e = -a + 10;     // 7
Printf("a=%g b=%g c=%g", a, b, c);
Printf("d=%g e=%g", d, e);
Printf("compare %g %g %g", a < b, a == 3, b != 7);
Printf("fixed %.3f", c);
