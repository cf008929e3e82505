// Points embedded in a square where its boundary curves already have nodes (one of them twice):
// the surface mesh uses the boundary's nodes there.
Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25}; Point(3) = {1, 1, 0, 0.25}; Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(5) = {0.5, 1, 0, 0.05};
Point(6) = {0.25, 1, 0, 0.05};
Point(7) = {0.5, 1, 0, 0.05};
Point(8) = {0.5, 0.5, 0, 0.05};
Point{5, 6, 7, 8} In Surface{1};
