// A unit square whose opposite sides are periodic: the top side is the image of the bottom one
// by a translation along y, the right side that of the left one along x. The bottom side is
// refined towards its start, so the top one is too, at its matching end.
Point(1) = {0, 0, 0, 0.02};
Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 1, 0, 0.1};
Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Periodic Curve{3} = {1} Translate{0, 1, 0};
Periodic Curve{2} = {4} Translate{1, 0, 0};
