// Prism layer on the wall of a straight pipe (four extruded arcs), grown toward the axis along normals; run with -3.
R = 0.5;
H = 3;
lc = 0.12;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc};
Point(5) = {0, -R, 0, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
wall[] = {};
For c In {1 : 4}
  e[] = Extrude {0, 0, H} { Curve{c}; };
  wall[] += e[1];
EndFor

// the wall normals point outward (translated counter-clockwise arcs): negative heights go inward
out[] = Extrude { Surface{wall[]}; Layers{ {1, 1, 1, 1, 1}, {-0.004, -0.01, -0.02, -0.035, -0.06} }; Recombine; };
