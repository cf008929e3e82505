// 2D gasket outline: a rectangle with rounded corners and two disk holes.
SetFactory("OpenCASCADE");
w = 4; h = 2; rc = 0.4;
Rectangle(1) = {0, 0, 0, w, h, rc};
Disk(2) = {1, 1, 0, 0.35};
Disk(3) = {3, 1, 0, 0.35};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2,3}; Delete; }
Mesh.Algorithm = 5;
Mesh.MeshSizeMax = 0.08;
Physical Surface("gasket") = {1};
