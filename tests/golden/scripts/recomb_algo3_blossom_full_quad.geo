// Mesh.RecombinationAlgorithm = 3 (Blossom full-quad): a Blossom recombination, then every
// element is split into quadrangles (a triangle into three, a quadrangle into four). The
// surface is first meshed at twice the size asked for, so that the split mesh keeps it: the
// curves get twice as many segments as at lc 0.16.
Mesh.RecombinationAlgorithm = 3;
lc = 0.08;
Point(1) = {0, 0, 0, lc}; Point(2) = {2, 0, 0, lc}; Point(3) = {2, 1, 0, lc};
Point(4) = {1, 1, 0, lc}; Point(5) = {1, 2, 0, lc}; Point(6) = {0, 2, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};
Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Curve Loop(1) = {1:6};
Plane Surface(1) = {1};
Recombine Surface{1};
