// 2D: a thin plate (one line) in a box with a quadrangle layer on each side of it.
lc = 0.1;
Point(1) = {0.3, 0.5, 0, 0.02}; Point(2) = {0.7, 0.5, 0, 0.02};
Line(1) = {1, 2};
up[] = Extrude { Curve{1}; Layers{{1, 1, 1}, {0.01, 0.025, 0.045}}; Recombine; };
down[] = Extrude { Curve{1}; Layers{{1, 1, 1}, {-0.01, -0.025, -0.045}}; Recombine; Using Index[1]; };
