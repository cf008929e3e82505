// Rounded die: intersection of a cube and a sphere slightly larger than the cube's half-width.
SetFactory("OpenCASCADE");
Box(1) = {-1, -1, -1, 2, 2, 2};
Sphere(2) = {0, 0, 0, 1.35};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 0.12;
Physical Volume("die") = {3};
