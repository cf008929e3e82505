// A STEP part read with ShapeFromFile, then cut: the tags and counts the reference gives.
SetFactory("OpenCASCADE");
v() = ShapeFromFile("occ_bracket.step");
s() = Surface{:}; c() = Curve{:}; p() = Point{:};
Printf("read %g volume(s), first %g: %g surfaces, %g curves, %g points", #v(), v(0), #s(), #c(), #p());
b() = BoundingBox Volume{v(0)};
Printf("box %.6g %.6g %.6g %.6g %.6g %.6g", b(0), b(1), b(2), b(3), b(4), b(5));
Box(10) = {2, -1, -1, 3, 4, 3};
r() = BooleanDifference{ Volume{v(0)}; Delete; }{ Volume{10}; Delete; };
s() = Surface{:}; c() = Curve{:}; p() = Point{:};
Printf("cut: %g volume(s), first %g: %g surfaces, %g curves, %g points", #r(), r(0), #s(), #c(), #p());
f() = Boundary{ Volume{r(0)}; };
Printf("its faces: %g, first %g, last %g", #f(), f(0), f(#f() - 1));
