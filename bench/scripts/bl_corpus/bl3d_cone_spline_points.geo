// Cone frustum made by revolving a line in three 120-degree turns, prism layer along normals with Geometry.ExtrudeSplinePoints = 10; run with -3.
Geometry.ExtrudeSplinePoints = 10;
lc = 0.07;
Point(1) = {1.0, 0, 0, lc};
Point(2) = {0.4, 0, 1.2, lc};
Line(1) = {1, 2};
cone[] = {};
gen = 1;
For q In {1 : 3}
  e[] = Extrude { {0, 0, 1}, {0, 0, 0}, 2 * Pi / 3 } { Curve{gen}; };
  gen = e[0];
  cone[] += e[1];
EndFor

// the revolved faces' normals point toward the axis: a negative height puts the layer outside
out[] = Extrude { Surface{cone[]}; Layers{ {3, 2}, {-0.03, -0.08} }; Recombine; };
