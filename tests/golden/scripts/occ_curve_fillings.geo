// Surfaces bounded by loops of B-spline and of Bezier curves (BSpline Surface, Bezier Surface).
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.1;

Point(1) = {0, 0, 0};
Point(2) = {0.5, -0.2, 0.2};
Point(3) = {1, 0, 0};
Point(4) = {1.2, 0.5, 0.3};
Point(5) = {1, 1, 0};
Point(6) = {0.5, 1.2, -0.2};
Point(7) = {0, 1, 0};
Point(8) = {-0.2, 0.5, 0.1};
BSpline(1) = {1, 2, 3};
BSpline(2) = {3, 4, 5};
BSpline(3) = {5, 6, 7};
BSpline(4) = {7, 8, 1};
Curve Loop(1) = {1:4};
BSpline Surface(1) = {1};

// The same control points two higher, joined by Bezier curves.
Translate {0, 0, 2} { Duplicata{ Point{1:8}; } }
Bezier(5) = {9, 10, 11};
Bezier(6) = {11, 12, 13};
Bezier(7) = {13, 14, 15};
Bezier(8) = {15, 16, 9};
Curve Loop(10) = {5:8};
Bezier Surface(2) = {10};

b() = Boundary{ Surface{1}; };
Printf("the B-spline surface has %g curves", #b());
bb() = BoundingBox Surface{1};
Printf("its box: %.4f %.4f %.4f %.4f %.4f %.4f", bb(0), bb(1), bb(2), bb(3), bb(4), bb(5));
bb() = BoundingBox Surface{2};
Printf("the Bezier one's: %.4f %.4f %.4f %.4f %.4f %.4f", bb(0), bb(1), bb(2), bb(3), bb(4), bb(5));
c() = Curve{:};
Printf("model: %g curves", #c());
