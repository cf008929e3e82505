// Quad-dominant 2D plate with a hole using Mesh.RecombineAll and Frontal-Delaunay for quads.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 2, 1};
Disk(2) = {0.6, 0.5, 0, 0.2};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Mesh.Algorithm = 8;
Mesh.RecombineAll = 1;
Mesh.MeshSizeMax = 0.05;
Physical Surface("plate") = {1};
