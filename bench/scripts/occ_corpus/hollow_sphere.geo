// Thick spherical shell (pressure vessel): outer sphere minus inner sphere.
SetFactory("OpenCASCADE");
Ro = 1.0; Ri = 0.7;
Sphere(1) = {0, 0, 0, Ro};
Sphere(2) = {0, 0, 0, Ri};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 0.1;
Mesh.Algorithm3D = 1;
Physical Volume("shell") = {3};
Physical Surface("outer") = {1};
Physical Surface("inner") = {2};
