// A quarter torus pipe elbow meshed with quadratic (second-order) tetrahedra.
SetFactory("OpenCASCADE");
Torus(1) = {0, 0, 0, 1, 0.3, Pi/2};
Mesh.ElementOrder = 2;
Mesh.HighOrderOptimize = 1;
Mesh.MeshSizeMax = 0.1;
Physical Volume("elbow") = {1};
