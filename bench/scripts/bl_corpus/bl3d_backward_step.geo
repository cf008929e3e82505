// Backward-facing step walls (a convex and a concave edge) with a prism layer, Mesh.BoundaryLayerFanElements set; run with -3.
Mesh.BoundaryLayerFanElements = 7;
h = 0.5;   // step height
W = 1;     // width
lc = 0.08;
Point(1) = {0, 0, h, lc};
Point(2) = {1, 0, h, lc};
Point(3) = {1, 0, 0, lc};
Point(4) = {3, 0, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
// the profile runs in +x, extruded in +y: normals point up and downstream, into the flow
walls[] = {};
For c In {1 : 3}
  e[] = Extrude {0, W, 0} { Curve{c}; };
  walls[] += e[1];
EndFor

out[] = Extrude { Surface{walls[]}; Layers{ {1, 1, 1, 1}, {0.004, 0.01, 0.02, 0.035} }; Recombine; };
