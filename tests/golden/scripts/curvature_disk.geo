// A unit disk bounded by four quarter circles with a size of 1 everywhere: the size from
// curvature (20 elements per full turn) is what refines the boundary.
Mesh.MeshSizeFromCurvature = 20;
Point(1) = {0, 0, 0, 1};
Point(2) = {1, 0, 0, 1};
Point(3) = {0, 1, 0, 1};
Point(4) = {-1, 0, 0, 1};
Point(5) = {0, -1, 0, 1};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1:4};
Plane Surface(1) = {1};
