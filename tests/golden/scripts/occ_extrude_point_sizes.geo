// The points an OpenCASCADE extrusion makes have the mesh sizes of the points they are swept
// from, as in the reference: the far ends of the swept edges are as fine as their sources, so
// the edges the sweeps make are meshed as finely as the profiles.
SetFactory("OpenCASCADE");
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 1, 0, 0.1};
Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Extrude {0, 0, 1} { Surface{1}; }
// A quarter turn of a square plate about the y axis.
Point(101) = {3, 0, 0, 0.2};
Point(102) = {4, 0, 0, 0.2};
Point(103) = {4, 1, 0, 0.2};
Point(104) = {3, 1, 0, 0.2};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Extrude {{0, 1, 0}, {0, 0, 0}, Pi/2} { Surface{101}; }
