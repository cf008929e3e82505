// A line from a point to itself: the reference warns and goes on; geomesh warns that it
// makes no curve and meshes the rest (here the four points).
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 1, 0, 0.1};
Point(4) = {0, 1, 0, 0.1};
Line(1) = {2, 2};
Line(2) = {1, 3};
