// Mesh.SubdivisionAlgorithm = 1: a plate with a round hole, meshed in triangles, then every
// triangle is split into three quadrangles and every curve segment into two.
Mesh.SubdivisionAlgorithm = 1;
lc = 0.1;
Point(1) = {0, 0, 0, lc}; Point(2) = {1.5, 0, 0, lc}; Point(3) = {1.5, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Point(5) = {0.75, 0.5, 0, lc}; Point(6) = {1.0, 0.5, 0, lc}; Point(7) = {0.5, 0.5, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 6};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6};
Plane Surface(1) = {1, 2};
