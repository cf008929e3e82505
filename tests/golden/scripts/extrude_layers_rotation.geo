// A square away from the axis turned by a quarter turn about the y axis, 10 layers of
// hexahedra and prisms.
Point(1) = {1, 0, 0, 0.2};
Point(2) = {2, 0, 0, 0.2};
Point(3) = {2, 1, 0, 0.2};
Point(4) = {1, 1, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Extrude{{0, 1, 0}, {0, 0, 0}, Pi/2}{Surface{1}; Layers{10}; Recombine;}
