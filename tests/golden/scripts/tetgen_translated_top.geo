// A triangular prism extruded without layers: its top is the exact translated copy of its
// bottom, which gives TetGen many exactly cospherical nodes. TetGen 1.5 aborts on this boundary
// in one order of its nodes; geomesh tries another order.
lc = 0.1;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Extrude {0, 0, 1} { Surface{1}; }
