// Mesh.RecombinationAlgorithm = 0 (simple): triangles are paired greedily, best quadrangle
// first, and those left without a free neighbour stay triangles; the angle given to Recombine
// Surface is not used by this algorithm.
Mesh.RecombinationAlgorithm = 0;
lc = 0.08;
Point(1) = {0, 0, 0, lc}; Point(2) = {2, 0, 0, lc}; Point(3) = {2, 1, 0, lc};
Point(4) = {1, 1, 0, lc}; Point(5) = {1, 2, 0, lc}; Point(6) = {0, 2, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};
Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Curve Loop(1) = {1:6};
Plane Surface(1) = {1};
Recombine Surface{1} = 20;
