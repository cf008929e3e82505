// Circle arcs of exactly half a turn: as in the reference, their plane is z = constant through
// the center and they turn clockwise seen from +z, whichever way the diameter points. Arcs
// short of half a turn, even by a rounding error, keep the plane and sense of their points.
SetFactory("OpenCASCADE");

// A half disk cut out of a 2 x 2 square: the arc bulges away from the square.
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

Macro PrintBox
  b() = BoundingBox Curve{c};
  Printf("curve %g: %.4f %.4f %.4f %.4f %.4f %.4f", c, b(0), b(1), b(2), b(3), b(4), b(5));
Return

c = 1; Call PrintBox;
// Diameters along other directions, around a center off the origin.
Point(10) = {10, 20, 3};
Point(11) = {11, 21, 3};
Point(12) = {9, 19, 3};
Circle(5) = {11, 10, 12};
c = 5; Call PrintBox;
Circle(6) = {12, 10, 11};
c = 6; Call PrintBox;
Point(13) = {10.6, 19.2, 3};
Point(14) = {9.4, 20.8, 3};
Circle(7) = {13, 10, 14};
c = 7; Call PrintBox;
// Ends computed with Sin(Pi) around the origin: not exactly opposite, so the arc keeps the
// plane and sense of its points (counter-clockwise here).
Point(15) = {1, 0, 5};
Point(16) = {0, 0, 5};
Point(17) = {Cos(Pi), Sin(Pi), 5};
Circle(8) = {15, 16, 17};
c = 8; Call PrintBox;
