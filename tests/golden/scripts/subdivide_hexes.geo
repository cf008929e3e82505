// Mesh.SubdivisionAlgorithm = 2: after meshing the volume in tetrahedra, each is split into 4
// hexahedra (through the middles of its edges, the centres of its faces and its own centre),
// each boundary triangle into 3 quadrangles and each segment into 2.
Mesh.SubdivisionAlgorithm = 2;
lc = 0.25;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 0.6, 0, lc};
Point(4) = {0, 0.6, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1:4};
Plane Surface(1) = {1};
Extrude {0, 0, 0.4} { Surface{1}; }
