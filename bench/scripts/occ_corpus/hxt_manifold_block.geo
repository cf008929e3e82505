// A hydraulic manifold block with three drilled intersecting channels, meshed with the HXT 3D algorithm.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 3, 2, 1.5};
Cylinder(2) = {-0.1, 1, 0.75, 3.2, 0, 0, 0.25};
Cylinder(3) = {1, -0.1, 0.75, 0, 1.2, 0, 0.2};
Cylinder(4) = {2, 1, -0.1, 0, 0, 1, 0.2};
Cylinder(5) = {2.2, -0.1, 0.4, 0, 2.2, 0, 0.12};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2:5}; Delete; }
Mesh.Algorithm3D = 10;
Mesh.MeshSizeMax = 0.12;
Mesh.MeshSizeMin = 0.03;
Mesh.MeshSizeFromCurvature = 10;
Physical Volume("manifold") = {1};
