// Prism layer grown outward on five faces of a box (the face on the ground is left bare), convex edges and corners; run with -3.
lc = 0.1;
a = 1;
Point(1) = {0, 0, 0, lc};
Point(2) = {a, 0, 0, lc};
Point(3) = {a, a, 0, lc};
Point(4) = {0, a, 0, lc};
Point(5) = {0, 0, a, lc};
Point(6) = {a, 0, a, lc};
Point(7) = {a, a, a, lc};
Point(8) = {0, a, a, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
// loops turn counter-clockwise seen from outside: normals point out of the box
Curve Loop(1) = {1, 10, -5, -9};  Plane Surface(1) = {1};  // y = 0
Curve Loop(2) = {2, 11, -6, -10}; Plane Surface(2) = {2};  // x = a
Curve Loop(3) = {3, 12, -7, -11}; Plane Surface(3) = {3};  // y = a
Curve Loop(4) = {4, 9, -8, -12};  Plane Surface(4) = {4};  // x = 0
Curve Loop(5) = {5, 6, 7, 8};     Plane Surface(5) = {5};  // z = a
Curve Loop(6) = {-4, -3, -2, -1}; Plane Surface(6) = {6};  // z = 0, the ground

out[] = Extrude { Surface{1:5}; Layers{ {1, 1, 1}, {0.01, 0.03, 0.07} }; Recombine; };
