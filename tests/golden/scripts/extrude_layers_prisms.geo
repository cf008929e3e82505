// A disc swept into a cylinder of prisms, with graded layers.
Point(1) = {0, 0, 0, 0.2};
Point(2) = {1, 0, 0, 0.2};
Point(3) = {0, 1, 0, 0.2};
Point(4) = {-1, 0, 0, 0.2};
Point(5) = {0, -1, 0, 0.2};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Extrude{0, 0, 2}{Surface{1}; Layers{{3, 2}, {0.5, 1}}; Recombine;}
