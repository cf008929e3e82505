// A rock block with an internal fracture plane: a rectangle embedded in the volume with Surface In Volume.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Rectangle(10) = {0.5, 0.25, 0.5, 1, 0.5};
Surface{10} In Volume{1};
MeshSize{ PointsOf{ Surface{10}; } } = 0.04;
Mesh.MeshSizeMax = 0.12;
Physical Volume("rock") = {1};
Physical Surface("fracture") = {10};
