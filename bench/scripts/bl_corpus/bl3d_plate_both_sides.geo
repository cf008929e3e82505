// A plate inside a box with a prism layer on both of its sides.
lc = 0.1;
Point(1) = {0.3, 0.3, 0.5, lc/2}; Point(2) = {0.7, 0.3, 0.5, lc/2};
Point(3) = {0.7, 0.7, 0.5, lc/2}; Point(4) = {0.3, 0.7, 0.5, lc/2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
up[] = Extrude { Surface{1}; Layers{{1, 1, 1}, {0.01, 0.025, 0.045}}; Recombine; };
down[] = Extrude { Surface{1}; Layers{{1, 1, 1}, {-0.01, -0.025, -0.045}}; Recombine; Using Index[1]; };
