// A circle of two half arcs through points without sizes: the default size is a tenth of the
// diagonal of the points' box, whose zero y extent counts as twice its diagonal, so each half
// gets 8 segments as in the reference (the arcs bulging past the points do not count).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {-1, 0, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 2};
