// Slotted plate extruded to 3D: slot outline built from Points, Lines and Circle arcs in OCC.
SetFactory("OpenCASCADE");
lc = 0.1;
// outer square
Point(1) = {0, 0, 0, lc};
Point(2) = {3, 0, 0, lc};
Point(3) = {3, 2, 0, lc};
Point(4) = {0, 2, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
// obround slot with two half-circle ends
rs = 0.3;
Point(10) = {1, 1, 0, lc/2};
Point(11) = {2, 1, 0, lc/2};
Point(12) = {1, 1 - rs, 0, lc/2};
Point(13) = {2, 1 - rs, 0, lc/2};
Point(14) = {2, 1 + rs, 0, lc/2};
Point(15) = {1, 1 + rs, 0, lc/2};
Line(10) = {12, 13};
Circle(11) = {13, 11, 14};
Line(12) = {14, 15};
Circle(13) = {15, 10, 12};
Curve Loop(2) = {10, 11, 12, 13};
Plane Surface(1) = {1, 2};
Extrude {0, 0, 0.4} { Surface{1}; }
Physical Volume("plate") = {1};
