// Reduced: a 180-degree Circle arc (start, centre, end) inside a square hole bulges the other way in geomesh.
SetFactory("OpenCASCADE");
Point(1) = {0, 0, 0, 0.1};
Point(2) = {0, -1, 0, 0.1};
Point(3) = {0, 1, 0, 0.1};
Point(4) = {2, 1, 0, 0.1};
Point(5) = {2, -1, 0, 0.1};
Circle(1) = {2, 1, 3};
Line(2) = {3, 4};
Line(3) = {4, 5};
Line(4) = {5, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
