// A plain rectangular block 2 x 1 x 0.5 with a uniform max element size.
SetFactory("OpenCASCADE");

L = 2.0; W = 1.0; H = 0.5;
lc = 0.08;

Box(1) = {0, 0, 0, L, W, H};

Mesh.MeshSizeMax = lc;
Mesh.MeshSizeMin = lc / 4;

Physical Volume("solid") = {1};
Physical Surface("bottom") = {5};
Physical Surface("top") = {6};
