// A face, a curve and a point fragmented with a box stay inside it as internal parts: the
// tetrahedra conform to them, as to entities embedded with `In Volume`.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Rectangle(10) = {0.5, 0.25, 0.5, 1, 0.5};
Point(100) = {0.2, 0.5, 0.2, 0.05};
Point(101) = {1.8, 0.5, 0.2, 0.05};
Line(100) = {100, 101};
Point(102) = {1, 0.5, 0.85, 0.05};
BooleanFragments{ Volume{1}; Delete; }{ Surface{10}; Curve{100}; Point{102}; Delete; }
MeshSize{ PointsOf{ Surface{10}; } } = 0.04;
Mesh.MeshSizeMax = 0.12;
Physical Volume("box") = {1};
Physical Surface("crack") = {10};
