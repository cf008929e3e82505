// A plane surface whose loop is only nearly plane is meshed on its mean plane, with a warning
// giving the deviation; a Nurbs curve (no weights in .geo) and a Line through several points.
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0.01, 0.1};
Point(3) = {1, 1, 0, 0.1};
Point(4) = {0, 1, 0.01, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(5) = {0, 0, 3}; Point(6) = {1, 1, 3}; Point(7) = {2, 1, 3}; Point(8) = {3, 0, 3};
Nurbs(5) = {5, 6, 7, 8} Knots {0, 0, 0, 0, 1, 1, 1, 1} Order 3;
Line(6) = {5, 6, 7, 8};
Transfinite Curve{5, 6} = 5;
Physical Surface("plate") = {1};
Physical Curve("curves") = {5, 6};
