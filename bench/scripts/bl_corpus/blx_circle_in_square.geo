// 2D: quadrangle layer extruded along the normals of a circle's four arcs, triangles between the layer's top curves and a square; run with -3.
R = 0.5;
L = 2;
lc = 0.05;
lcFar = 0.2;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc};
Point(5) = {0, -R, 0, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};

out[] = Extrude { Curve{1:4}; Layers{ {1, 1, 1, 1}, {0.005, 0.015, 0.03, 0.05} }; Recombine; };

// each arc returns {top curve, layer surface, two sides}
tops[] = {};
layer[] = {};
For i In {0 : 3}
  tops[] += out[4 * i];
  layer[] += out[4 * i + 1];
EndFor

p = newp;
Point(p)     = {-L, -L, 0, lcFar};
Point(p + 1) = { L, -L, 0, lcFar};
Point(p + 2) = { L,  L, 0, lcFar};
Point(p + 3) = {-L,  L, 0, lcFar};
l = newl;
Line(l)     = {p, p + 1};
Line(l + 1) = {p + 1, p + 2};
Line(l + 2) = {p + 2, p + 3};
Line(l + 3) = {p + 3, p};
cl = newcl;
Curve Loop(cl) = {l : l + 3};
Curve Loop(cl + 1) = {tops[]};
s = news;
Plane Surface(s) = {cl, cl + 1};
