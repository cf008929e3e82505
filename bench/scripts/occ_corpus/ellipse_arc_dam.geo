// An arch-dam-like block: profile closed by a quarter Ellipse arc and two lines, extruded along y.
SetFactory("OpenCASCADE");
// quarter ellipse centred at the origin, semi-axes 2 (x) and 1.2 (z), in the xz-plane
Ellipse(1) = {0, 0, 0, 2, 1.2, 0, Pi/2};
Rotate{ {1, 0, 0}, {0, 0, 0}, Pi/2 } { Curve{1}; }
b() = PointsOf{ Curve{1}; };
Printf("arc end points %g %g", b(0), b(1));
Point(10) = {0, 0, 0};
Line(2) = {b(1), 10};
Line(3) = {10, b(0)};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
e() = Extrude {0, 3, 0} { Surface{1}; };
Mesh.MeshSizeMax = 0.1;
Physical Volume("dam") = {e(1)};
