// A cushion: two Surface fillings on the same four BSpline edges, bulged by a point each, closed into a volume.
SetFactory("OpenCASCADE");
lc = 0.06;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Point(5) = {0.5, -0.1, 0.05}; Point(6) = {1.1, 0.5, -0.05}; Point(7) = {0.5, 1.1, 0.05}; Point(8) = {-0.1, 0.5, -0.05};
BSpline(1) = {1, 5, 2};
BSpline(2) = {2, 6, 3};
BSpline(3) = {3, 7, 4};
BSpline(4) = {4, 8, 1};
Curve Loop(1) = {1, 2, 3, 4};
Point(20) = {0.5, 0.5, 0.25};
Point(21) = {0.5, 0.5, -0.25};
Surface(1) = {1} Using Point{20};
Surface(2) = {1} Using Point{21};
Surface Loop(1) = {1, 2};
Volume(1) = {1};
Mesh.MeshSizeMax = lc;
Physical Volume("cushion") = {1};
Physical Surface("cover") = {1, 2};
