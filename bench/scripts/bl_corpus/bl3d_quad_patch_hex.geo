// Transfinite, recombined quarter-cylinder patch extruded along its normals: hexahedral layer; run with -3.
R = 1;
H = 2;
Point(1) = {0, 0, 0, 0.1};
Point(2) = {R, 0, 0, 0.1};
Point(3) = {0, R, 0, 0.1};
Point(4) = {0, 0, H, 0.1};
Point(5) = {R, 0, H, 0.1};
Point(6) = {0, R, H, 0.1};
Circle(1) = {2, 1, 3};
Circle(2) = {5, 4, 6};
Line(3) = {2, 5};
Line(4) = {3, 6};
Curve Loop(1) = {1, 4, -2, -3};
Surface(1) = {1};
Transfinite Curve{1, 2} = 16;
Transfinite Curve{3, 4} = 21;
Transfinite Surface{1};
Recombine Surface{1};

out[] = Extrude { Surface{1}; Layers{ {1, 1, 1, 1, 1}, {0.005, 0.015, 0.03, 0.05, 0.08} }; Recombine; };
