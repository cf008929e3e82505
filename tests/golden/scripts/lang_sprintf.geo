// Printf and Sprintf number formats: %g %e %f %G %E with widths, precisions and flags.
x = 1234.56789;
Printf("%g|%e|%f|%.2f|%10.3f|%-10.1f|", x, x, x, x, x, x);
Printf("%G %E", 1e-10, 12345.678);
Printf("%.0f %.0f %.0f", 0.5, 1.5, 2.5);
Printf("%5.1e", 0.000123);
Printf("%g %g %g %g", 1e20, 1e-5, 0.0001, 123456789);
Printf("%g %g", 1/3, -2/3);
Printf("%+g % g %+.2e", 5, 5, -5);
l() = {1, 2, 3};
Printf("%g %g %g", l());
Printf(Sprintf("%g and %g", 1.5, 2.5));
Printf("%g", 0.1 + 0.2);
Printf("%.17g", 0.1);
