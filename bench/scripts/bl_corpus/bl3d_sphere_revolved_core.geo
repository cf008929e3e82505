// Sphere made by revolving two quarter arcs, layer grown inward with negative heights, tetrahedral core inside, physical groups; run with -3.
R = 1;
lc = 0.12;
Point(1) = {0, 0, 0, lc};
Point(2) = {0, 0, R, lc};
Point(3) = {R, 0, 0, lc};
Point(4) = {0, 0, -R, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
shell[] = {};
arcs[] = {1, 2};
For q In {0 : 3}
  // each arc gives {new arc, surface, one side}: the side at the pole is degenerate
  e[] = Extrude { {0, 0, 1}, {0, 0, 0}, Pi / 2 } { Curve{arcs[]}; };
  shell[] += {e[1], e[4]};
  arcs[] = {e[0], e[3]};
EndFor

out[] = Extrude { Surface{shell[]}; Layers{ {1, 1, 1, 1}, {-0.01, -0.025, -0.045, -0.07} }; Recombine; };

tops[] = {};
layer[] = {};
For i In {0 : #shell[] - 1}
  tops[] += out[5 * i];
  layer[] += out[5 * i + 1];
EndFor
sl = newsl;
Surface Loop(sl) = {tops[]};
core = newv;
Volume(core) = {sl};

Physical Surface("shell", 1) = {shell[]};
Physical Volume("layer", 2) = {layer[]};
Physical Volume("core", 3) = {core};
