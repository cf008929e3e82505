// An electrode in a tank (the occ_corpus case embedded_in_volume): a line and two points
// embedded in a box.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 2};
Point(100) = {0.5, 0.5, 0.5, 0.02};
Point(101) = {0.5, 0.5, 1.5, 0.02};
Line(100) = {100, 101};
Point(102) = {0.25, 0.7, 1.0, 0.03};
Point(103) = {0.75, 0.3, 1.0, 0.03};
Curve{100} In Volume{1};
Point{102, 103} In Volume{1};
Mesh.MeshSizeMax = 0.15;
Physical Volume("tank") = {1};
Physical Curve("electrode") = {100};
