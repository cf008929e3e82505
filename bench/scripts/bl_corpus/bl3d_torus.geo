// Torus made by revolving a circle in four quarter turns, prism layer grown along its normals (outward); run with -3.
R = 1;    // distance from the axis to the tube's centre
r = 0.3;  // tube radius
lc = 0.08;
Point(1) = {R, 0, 0, lc};
Point(2) = {R + r, 0, 0, lc};
Point(3) = {R, 0, r, lc};
Point(4) = {R - r, 0, 0, lc};
Point(5) = {R, 0, -r, lc};
// the section turns clockwise seen from +y, so that the revolved faces' normals point out of the tube
Circle(1) = {2, 1, 5};
Circle(2) = {5, 1, 4};
Circle(3) = {4, 1, 3};
Circle(4) = {3, 1, 2};
tube[] = {};
arcs[] = {1, 2, 3, 4};
For q In {1 : 4}
  e[] = Extrude { {0, 0, 1}, {0, 0, 0}, Pi / 2 } { Curve{arcs[]}; };
  arcs[] = {};
  For j In {0 : 3}
    arcs[] += e[4 * j];
    tube[] += e[4 * j + 1];
  EndFor
EndFor

out[] = Extrude { Surface{tube[]}; Layers{ {1, 1, 1}, {0.006, 0.015, 0.03} }; Recombine; };
