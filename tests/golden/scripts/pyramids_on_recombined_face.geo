// A box meshed with tetrahedra whose bottom face is recombined: each quadrangle of the
// bottom carries a pyramid, apex inside the box, as the reference meshes it.
Point(1) = {0, 0, 0, 0.25};
Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 1, 0, 0.25};
Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1:4} = 5;
Transfinite Surface{1};
Recombine Surface{1};
Extrude {0, 0, 1} { Surface{1}; }
