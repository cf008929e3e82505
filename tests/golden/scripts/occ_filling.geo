// OpenCASCADE fillings: bounded by the script's own curves, and through constraint points.
SetFactory("OpenCASCADE");

Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0.4};
Point(3) = {2, 1.5, 0};
Point(4) = {0, 1.5, 0.3};
Point(5) = {1, -0.3, 0.1};
Spline(1) = {1, 5, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1};
b() = Boundary{ Surface{1}; };
// The order in which the boundary lists the curves depends on which way the filling's surface
// faces: only the set of curves is printed.
Printf("plain filling: %g curves, tags adding up to %g", #b(), Abs(b(0)) + Abs(b(1)) + Abs(b(2)) + Abs(b(3)));

// The same loop, lifted through a point in its middle.
Translate {0, 0, 2} { Duplicata{ Curve{1:4}; } }
Curve Loop(10) = {5:8};
Point(20) = {1, 0.75, 2.8};
Surface(2) = {10} Using Point{20};
b() = Boundary{ Surface{2}; };
Printf("constrained filling: %g curves, tags adding up to %g", #b(), Abs(b(0)) + Abs(b(1)) + Abs(b(2)) + Abs(b(3)));
bb() = BoundingBox Surface{2};
Printf("constrained filling rises to z = %.4f", bb(5));
c() = Curve{:};
p() = Point{:};
Printf("model: %g curves, %g points", #c(), #p());
