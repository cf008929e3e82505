// T-junction pipe body: union of two solid cylinders.
SetFactory("OpenCASCADE");
r1 = 0.5; r2 = 0.3;
Cylinder(1) = {-2, 0, 0, 4, 0, 0, r1};
Cylinder(2) = {0, 0, 0, 0, 0, 1.5, r2};
BooleanUnion(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 0.12;
Physical Volume("tee") = {3};
