// A quarter of an annulus whose two straight sides are periodic under a quarter turn about z
// (the side on the y axis is the image of the side on the x axis, run the other way).
Point(1) = {0, 0, 0, 0.2};
Point(2) = {1, 0, 0, 0.2};
Point(3) = {0, 1, 0, 0.2};
Point(4) = {2, 0, 0, 0.05};
Point(5) = {0, 2, 0, 0.05};
Line(1) = {2, 4};
Circle(2) = {4, 1, 5};
Line(3) = {5, 3};
Circle(4) = {3, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Periodic Curve{3} = {1} Rotate{{0, 0, 1}, {0, 0, 0}, Pi / 2};
