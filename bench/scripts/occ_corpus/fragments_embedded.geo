// 2D square plate with a crack line and two sensor points made conformal via BooleanFragments.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 2, 2};
Point(100) = {0.5, 1.0, 0};
Point(101) = {1.4, 1.2, 0};
Line(100) = {100, 101};
Point(102) = {1.5, 0.5, 0};
Point(103) = {0.4, 1.6, 0};
BooleanFragments{ Surface{1}; Delete; }{ Curve{100}; Point{102, 103}; Delete; }
Mesh.MeshSizeMax = 0.1;
MeshSize{ 102, 103 } = 0.02;
Physical Surface("plate") = {1};
