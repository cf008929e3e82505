// A representative volume element: a box with a spherical inclusion, opposite faces meshed periodically.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Sphere(2) = {0.5, 0.5, 0.5, 0.25};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.MeshSizeMax = 0.08;
// faces x = 0 / x = 1, y = 0 / y = 1, z = 0 / z = 1
sx0() = Surface In BoundingBox{-0.01, -0.01, -0.01, 0.01, 1.01, 1.01};
sx1() = Surface In BoundingBox{0.99, -0.01, -0.01, 1.01, 1.01, 1.01};
sy0() = Surface In BoundingBox{-0.01, -0.01, -0.01, 1.01, 0.01, 1.01};
sy1() = Surface In BoundingBox{-0.01, 0.99, -0.01, 1.01, 1.01, 1.01};
sz0() = Surface In BoundingBox{-0.01, -0.01, -0.01, 1.01, 1.01, 0.01};
sz1() = Surface In BoundingBox{-0.01, -0.01, 0.99, 1.01, 1.01, 1.01};
Periodic Surface{sx1(0)} = {sx0(0)} Translate{1, 0, 0};
Periodic Surface{sy1(0)} = {sy0(0)} Translate{0, 1, 0};
Periodic Surface{sz1(0)} = {sz0(0)} Translate{0, 0, 1};
Physical Volume("matrix") = {3};
Physical Volume("inclusion") = {2};
