// A line swept with graded layers, without Recombine: each quadrangle of the layers is cut
// into two triangles.
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0, 0.1};
Line(1) = {1, 2};
Extrude{0, 1, 0}{Curve{1}; Layers{{2, 3}, {0.3, 1}};}
