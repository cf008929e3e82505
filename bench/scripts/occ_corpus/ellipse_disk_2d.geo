// 2D elliptical membrane (Disk with two radii) with a circular hole, Frontal-Delaunay.
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 3, 1.5};
Disk(2) = {0.8, 0, 0, 0.4};
BooleanDifference(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
Mesh.Algorithm = 6;
Mesh.MeshSizeFromCurvature = 12;
Mesh.MeshSizeMax = 0.2;
Physical Surface("membrane") = {3};
Physical Curve("rim") = {1};
