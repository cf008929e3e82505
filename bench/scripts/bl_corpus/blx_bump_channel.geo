// 2D channel over a trapezoidal bump: quadrangle layer extruded along the normals of a polyline wall, triangles above it, physical groups; run with -3.
lc = 0.04;
lcFar = 0.12;
Hc = 1;   // channel height
// the wall runs from right to left so that its normals point up, into the channel
Point(1) = {3, 0, 0, lc};
Point(2) = {2, 0, 0, lc};
Point(3) = {1.7, 0.2, 0, lc};
Point(4) = {1.3, 0.2, 0, lc};
Point(5) = {1, 0, 0, lc};
Point(6) = {0, 0, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
wall[] = {1:5};

out[] = Extrude { Curve{wall[]}; Layers{ {1, 1, 1, 1}, {0.004, 0.012, 0.025, 0.045} }; Recombine; };

// per wall line: {top curve, layer surface, side at its end, side at its start}
layer[] = {};
topsReversed[] = {};
For i In {0 : #wall[] - 1}
  layer[] += out[4 * i + 1];
  topsReversed[] += -out[4 * (#wall[] - 1 - i)];
EndFor
sideOut = Abs(out[3]);                // side at the first point, x = 3
sideIn = Abs(out[4 * #wall[] - 2]);   // side at the last point, x = 0
b[] = Boundary{ Curve{out[0]}; };
cornerOut = b[0];
b[] = Boundary{ Curve{out[4 * #wall[] - 4]}; };
cornerIn = b[1];

p = newp;
Point(p) = {3, Hc, 0, lcFar};
Point(p + 1) = {0, Hc, 0, lcFar};
l = newl;
Line(l) = {cornerOut, p};
Line(l + 1) = {p, p + 1};
Line(l + 2) = {p + 1, cornerIn};
cl = newcl;
Curve Loop(cl) = {topsReversed[], l, l + 1, l + 2};
fluid = news;
Plane Surface(fluid) = {cl};

Physical Curve("wall", 1) = {wall[]};
Physical Curve("inlet", 2) = {l + 2, sideIn};
Physical Curve("outlet", 3) = {l, sideOut};
Physical Curve("top", 4) = {l + 1};
Physical Surface("fluid", 10) = {layer[], fluid};
