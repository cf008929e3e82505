// A saddle-shaped membrane: Surface filling bounded by four spline edges (2D model).
SetFactory("OpenCASCADE");
h = 0.3;
Point(1) = {0, 0, h};  Point(2) = {1, 0, -h}; Point(3) = {1, 1, h}; Point(4) = {0, 1, -h};
Point(5) = {0.5, -0.05, 0}; Point(6) = {1.05, 0.5, 0}; Point(7) = {0.5, 1.05, 0}; Point(8) = {-0.05, 0.5, 0};
Spline(1) = {1, 5, 2};
Spline(2) = {2, 6, 3};
Spline(3) = {3, 7, 4};
Spline(4) = {4, 8, 1};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1};
Mesh.MeshSizeMax = 0.04;
Mesh.Algorithm = 1;
Physical Surface("membrane") = {1};
