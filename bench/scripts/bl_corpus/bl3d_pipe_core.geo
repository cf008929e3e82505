// Pipe flow domain: prism layer inside the wall, tetrahedral core closed by caps on the layer's top curves, physical groups; run with -3.
R = 0.4;
H = 2;
lc = 0.1;
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

out[] = Extrude { Surface{wall[]}; Layers{ {2, 2, 2}, {-0.01, -0.03, -0.06} }; Recombine; };

// {top, volume, 4 sides} per wall patch; a wall patch's boundary is {arc at z = 0, side, arc at
// z = H, side}, so sides 2 and 4 of its layer are the annuli at the inlet and at the outlet, and
// the third curve of each annulus (bottom, side, top, side) is the layer's top edge there
tops[] = {};
layer[] = {};
ringIn[] = {};
ringOut[] = {};
capIn[] = {};
capOut[] = {};
For i In {0 : #wall[] - 1}
  tops[] += out[6 * i];
  layer[] += out[6 * i + 1];
  ringIn[] += out[6 * i + 2];
  ringOut[] += out[6 * i + 4];
  b[] = Boundary{ Surface{out[6 * i + 2]}; };
  capIn[] += Abs(b[2]);
  b[] = Boundary{ Surface{out[6 * i + 4]}; };
  capOut[] += Abs(b[2]);
EndFor

cl = newcl;
Curve Loop(cl) = {capIn[]};
Curve Loop(cl + 1) = {capOut[]};
s1 = news;
Plane Surface(s1) = {cl};
s2 = news;
Plane Surface(s2) = {cl + 1};
sl = newsl;
Surface Loop(sl) = {tops[], s1, s2};
core = newv;
Volume(core) = {sl};

Physical Surface("wall", 1) = {wall[]};
Physical Surface("inlet", 2) = {s1, ringIn[]};
Physical Surface("outlet", 3) = {s2, ringOut[]};
Physical Volume("fluid", 4) = {layer[], core};
