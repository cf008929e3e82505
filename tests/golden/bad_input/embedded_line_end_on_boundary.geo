// A slit from the middle of the top side down into a rectangle: the top side is one line, not
// split at the slit's end, so the slit's end point is not a point of the boundary.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {3, 0, 0, 0.1}; Point(3) = {3, 2, 0, 0.1}; Point(4) = {0, 2, 0, 0.1};
Point(5) = {1.5, 2, 0, 0.1}; Point(6) = {1.5, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Line{5} In Surface{1};
