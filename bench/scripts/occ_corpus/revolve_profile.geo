// Axisymmetric flanged bushing: a planar profile revolved 360 degrees about the z axis.
SetFactory("OpenCASCADE");
lc = 0.06;
Point(1) = {0.3, 0, 0, lc};
Point(2) = {0.8, 0, 0, lc};
Point(3) = {0.8, 0, 0.2, lc};
Point(4) = {0.5, 0, 0.2, lc};
Point(5) = {0.5, 0, 1.0, lc};
Point(6) = {0.3, 0, 1.0, lc};
For i In {1:5}
  Line(i) = {i, i+1};
EndFor
Line(6) = {6, 1};
Curve Loop(1) = {1:6};
Plane Surface(1) = {1};
Extrude { {0, 0, 1}, {0, 0, 0}, 2*Pi } { Surface{1}; }
Physical Volume("bushing") = {1};
