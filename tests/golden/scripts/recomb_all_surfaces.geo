// Mesh.RecombineAll = 1 recombines every surface without a Recombine statement: here a square
// cut in two by a quarter circle, both parts in quadrangles.
Mesh.RecombineAll = 1;
lc = 0.06;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Point(5) = {0.6, 0, 0, lc}; Point(6) = {0, 0.6, 0, lc};
Line(1) = {1, 5}; Line(2) = {5, 2}; Line(3) = {2, 3}; Line(4) = {3, 4}; Line(5) = {4, 6};
Line(6) = {6, 1};
Circle(7) = {5, 1, 6};
Curve Loop(1) = {1, 7, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, 5, -7}; Plane Surface(2) = {2};
