// Sphere in a box: prism layer on the sphere, tetrahedra between the layer's top and the box, physical groups; run with -3.
lc = 0.15;
lcFar = 0.6;
R = 0.5;
L = 2;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc};
Point(5) = {0, -R, 0, lc};
Point(6) = {0, 0, R, lc};
Point(7) = {0, 0, -R, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Circle(5) = {3, 1, 6};
Circle(6) = {6, 1, 5};
Circle(7) = {5, 1, 7};
Circle(8) = {7, 1, 3};
Circle(9) = {2, 1, 7};
Circle(10) = {7, 1, 4};
Circle(11) = {4, 1, 6};
Circle(12) = {6, 1, 2};
Curve Loop(21) = {10, -8, -2};  Surface(31) = {21};
Curve Loop(22) = {-7, -3, -10}; Surface(32) = {22};
Curve Loop(23) = {-1, 9, 8};    Surface(33) = {23};
Curve Loop(24) = {-5, 2, 11};   Surface(34) = {24};
Curve Loop(25) = {1, 12, 5};    Surface(35) = {25};
Curve Loop(26) = {-6, -11, 3};  Surface(36) = {26};
Curve Loop(27) = {-9, -4, 7};   Surface(37) = {27};
Curve Loop(28) = {6, -12, 4};   Surface(38) = {28};
sphere[] = {31:38};

out[] = Extrude { Surface{sphere[]}; Layers{ {1, 1, 1}, {0.02, 0.05, 0.1} }; Recombine; };

// each extruded patch returns {top, volume, sides...}: 5 entries for a triangle-bounded patch
tops[] = {};
layer[] = {};
For i In {0 : #sphere[] - 1}
  tops[] += out[5 * i];
  layer[] += out[5 * i + 1];
EndFor

// the box, numbered after everything the extrusion created
p = newp;
Point(p)     = {-L, -L, -L, lcFar};
Point(p + 1) = { L, -L, -L, lcFar};
Point(p + 2) = { L,  L, -L, lcFar};
Point(p + 3) = {-L,  L, -L, lcFar};
Point(p + 4) = {-L, -L,  L, lcFar};
Point(p + 5) = { L, -L,  L, lcFar};
Point(p + 6) = { L,  L,  L, lcFar};
Point(p + 7) = {-L,  L,  L, lcFar};
l = newl;
Line(l)      = {p, p + 1};     Line(l + 1)  = {p + 1, p + 2};
Line(l + 2)  = {p + 2, p + 3}; Line(l + 3)  = {p + 3, p};
Line(l + 4)  = {p + 4, p + 5}; Line(l + 5)  = {p + 5, p + 6};
Line(l + 6)  = {p + 6, p + 7}; Line(l + 7)  = {p + 7, p + 4};
Line(l + 8)  = {p, p + 4};     Line(l + 9)  = {p + 1, p + 5};
Line(l + 10) = {p + 2, p + 6}; Line(l + 11) = {p + 3, p + 7};
c = newcl;
Curve Loop(c)     = {l, l + 1, l + 2, l + 3};
Curve Loop(c + 1) = {l + 4, l + 5, l + 6, l + 7};
Curve Loop(c + 2) = {l, l + 9, -(l + 4), -(l + 8)};
Curve Loop(c + 3) = {l + 1, l + 10, -(l + 5), -(l + 9)};
Curve Loop(c + 4) = {l + 2, l + 11, -(l + 6), -(l + 10)};
Curve Loop(c + 5) = {l + 3, l + 8, -(l + 7), -(l + 11)};
box[] = {};
For k In {0 : 5}
  s = news;
  Plane Surface(s) = {c + k};
  box[] += s;
EndFor

sl = newsl;
Surface Loop(sl) = {box[]};
Surface Loop(sl + 1) = {tops[]};
v = newv;
Volume(v) = {sl, sl + 1};

Physical Surface("sphere", 1) = {sphere[]};
Physical Surface("farfield", 2) = {box[]};
Physical Volume("layer", 10) = {layer[]};
Physical Volume("air", 11) = {v};
