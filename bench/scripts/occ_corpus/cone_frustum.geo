// A conical frustum (nozzle-like taper) and a nearly sharp cone side by side, frontal 3D algorithm.
SetFactory("OpenCASCADE");
Cone(1) = {0, 0, 0, 0, 0, 2, 0.8, 0.3};
Cone(2) = {3, 0, 0, 0, 0, 1.5, 0.6, 0.1};
Mesh.MeshSizeMax = 0.1;
Mesh.Algorithm3D = 4;
Physical Volume("frustum") = {1};
Physical Volume("tip") = {2};
