// Layer without Recombine (tetrahedra) grown inward on all six faces of a box, tetrahedral core inside the layer, physical groups; run with -3.
lc = 0.15;
a = 1;
Point(1) = {0, 0, 0, lc};
Point(2) = {a, 0, 0, lc};
Point(3) = {a, a, 0, lc};
Point(4) = {0, a, 0, lc};
Point(5) = {0, 0, a, lc};
Point(6) = {a, 0, a, lc};
Point(7) = {a, a, a, lc};
Point(8) = {0, a, a, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
// loops turn clockwise seen from outside: normals point into the box
Curve Loop(1) = {9, 5, -10, -1};  Plane Surface(1) = {1};
Curve Loop(2) = {10, 6, -11, -2}; Plane Surface(2) = {2};
Curve Loop(3) = {11, 7, -12, -3}; Plane Surface(3) = {3};
Curve Loop(4) = {12, 8, -9, -4};  Plane Surface(4) = {4};
Curve Loop(5) = {-8, -7, -6, -5}; Plane Surface(5) = {5};
Curve Loop(6) = {1, 2, 3, 4};     Plane Surface(6) = {6};
walls[] = {1:6};

out[] = Extrude { Surface{walls[]}; Layers{ {2, 2}, {0.02, 0.05} }; };

tops[] = {};
layer[] = {};
For i In {0 : #walls[] - 1}
  tops[] += out[6 * i];
  layer[] += out[6 * i + 1];
EndFor
sl = newsl;
Surface Loop(sl) = {tops[]};
core = newv;
Volume(core) = {sl};

Physical Surface("walls", 1) = {walls[]};
Physical Volume("layer", 2) = {layer[]};
Physical Volume("core", 3) = {core};
