// A line swept into a surface of 5 layers of quadrangles, then that surface's top swept again
// with graded layers: 2 thin ones up to 0.2, then 3 up to the end.
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0, 0.1};
Line(1) = {1, 2};
e[] = Extrude{0, 1, 0}{Curve{1}; Layers{5}; Recombine;};
Extrude{0, 0.5, 0}{Curve{e[0]}; Layers{{2, 3}, {0.2, 1}}; Recombine;}
