// A solid ball of radius 1, meshed with a uniform target size.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Mesh.MeshSizeMin = 0.1;
Mesh.MeshSizeMax = 0.1;
Physical Volume("ball") = {1};
Physical Surface("skin") = {1};
