// A plate with four circular holes of different radii, meshed with Mesh.Algorithm = 8
// (Frontal-Delaunay for quadrangles) and recombined: quadrangles only, around every hole.
Mesh.Algorithm = 8;
lc = 0.1;
Point(1) = {0, 0, 0, lc}; Point(2) = {4, 0, 0, lc}; Point(3) = {4, 2, 0, lc}; Point(4) = {0, 2, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
// Each hole is a circle of centre (cx, cy) and radius cr, made of four arcs.
cx[] = {0.8, 2.0, 2.0, 3.2};
cy[] = {1.0, 0.6, 1.45, 1.0};
cr[] = {0.4, 0.25, 0.3, 0.5};
holes[] = {};
For i In {0 : #cx[] - 1}
  c = newp; Point(c) = {cx[i], cy[i], 0, lc};
  Point(c + 1) = {cx[i] + cr[i], cy[i], 0, lc}; Point(c + 2) = {cx[i], cy[i] + cr[i], 0, lc};
  Point(c + 3) = {cx[i] - cr[i], cy[i], 0, lc}; Point(c + 4) = {cx[i], cy[i] - cr[i], 0, lc};
  a = newc;
  Circle(a) = {c + 1, c, c + 2}; Circle(a + 1) = {c + 2, c, c + 3};
  Circle(a + 2) = {c + 3, c, c + 4}; Circle(a + 3) = {c + 4, c, c + 1};
  hole = newcl; Curve Loop(hole) = {a : a + 3};
  holes[] += hole;
EndFor
Plane Surface(1) = {1, holes[]};
Recombine Surface{1};
