// An ellipsoidal inclusion in a matrix block: a unit sphere stretched by a non-uniform Dilate, then fragmented.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Dilate{ {0, 0, 0}, {0.6, 0.35, 0.25} } { Volume{1}; }
Box(2) = {-1, -0.7, -0.6, 2, 1.4, 1.2};
f() = BooleanFragments{ Volume{2}; Delete; }{ Volume{1}; Delete; };
Printf("fragments %g %g", f(0), f(1));
Mesh.MeshSizeMax = 0.1;
Mesh.MeshSizeFromCurvature = 16;
Physical Volume("inclusion") = {1};
Physical Volume("matrix") = {f(0)};
