// Reduced: a closed OCC BSpline (first control point repeated last) is rejected by geomesh.
SetFactory("OpenCASCADE");
Point(1) = {1, 0, 0, 0.1};
Point(2) = {0, 1, 0, 0.1};
Point(3) = {-1, 0, 0, 0.1};
Point(4) = {0, -1, 0, 0.1};
BSpline(1) = {1, 2, 3, 4, 1};
Curve Loop(1) = {1};
Plane Surface(1) = {1};
