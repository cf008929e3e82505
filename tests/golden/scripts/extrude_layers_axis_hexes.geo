// A structured quadrangulated square with one side on the rotation axis, turned by a quarter
// turn with Recombine: the hexahedra next to the axis become prisms; the walls' quadrangles
// there become triangles.
Point(1) = {0, 0, 0, 0.25};
Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 1, 0, 0.25};
Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1};
Recombine Surface{1};
Extrude{{0, 1, 0}, {0, 0, 0}, Pi/2}{Surface{1}; Layers{6}; Recombine;}
