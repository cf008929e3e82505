Printf("%g and %g", 1);
