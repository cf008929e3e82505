// A square-to-round transition duct lofted through four wires (square, rounded square, octagon-like spline, circle).
SetFactory("OpenCASCADE");
// section 1: square z = 0
Point(1) = {-0.5, -0.5, 0}; Point(2) = {0.5, -0.5, 0}; Point(3) = {0.5, 0.5, 0}; Point(4) = {-0.5, 0.5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
// section 2: smaller square rotated, z = 0.6
a = 0.45; z = 0.6;
Point(5) = {-a, -a, z}; Point(6) = {a, -a, z}; Point(7) = {a, a, z}; Point(8) = {-a, a, z};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
// section 3: four circle arcs through the same corner directions, z = 1.2
z = 1.2; r = 0.45;
Point(9) = {0, 0, z};
Point(10) = {-r/Sqrt(2), -r/Sqrt(2), z}; Point(11) = {r/Sqrt(2), -r/Sqrt(2), z};
Point(12) = {r/Sqrt(2), r/Sqrt(2), z}; Point(13) = {-r/Sqrt(2), r/Sqrt(2), z};
Circle(9) = {10, 9, 11}; Circle(10) = {11, 9, 12}; Circle(11) = {12, 9, 13}; Circle(12) = {13, 9, 10};
Curve Loop(3) = {9, 10, 11, 12};
// section 4: smaller circle, z = 1.8
z = 1.8; r = 0.3;
Point(14) = {0, 0, z};
Point(15) = {-r/Sqrt(2), -r/Sqrt(2), z}; Point(16) = {r/Sqrt(2), -r/Sqrt(2), z};
Point(17) = {r/Sqrt(2), r/Sqrt(2), z}; Point(18) = {-r/Sqrt(2), r/Sqrt(2), z};
Circle(13) = {15, 14, 16}; Circle(14) = {16, 14, 17}; Circle(15) = {17, 14, 18}; Circle(16) = {18, 14, 15};
Curve Loop(4) = {13, 14, 15, 16};
ThruSections(1) = {1, 2, 3, 4};
Mesh.MeshSizeMax = 0.08;
Physical Volume("duct") = {1};
