// A curved shell patch: four Bezier edges bounding a Surface filling, thickened by extrusion.
SetFactory("OpenCASCADE");
Point(1) = {0, 0, 0};
Point(2) = {0.5, -0.2, 0.3};
Point(3) = {1, 0, 0};
Point(4) = {1.2, 0.5, 0.2};
Point(5) = {1, 1, 0};
Point(6) = {0.5, 1.2, 0.3};
Point(7) = {0, 1, 0};
Point(8) = {-0.2, 0.5, 0.2};
Bezier(1) = {1, 2, 3};
Bezier(2) = {3, 4, 5};
Bezier(3) = {5, 6, 7};
Bezier(4) = {7, 8, 1};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1};
Extrude {0, 0, 0.25} { Surface{1}; }
Mesh.MeshSizeMax = 0.06;
Physical Volume("shell") = {1};
