// The built-in kernel as users drive it: tags and result lists of Extrude, Rotate, Duplicata,
// Boundary and BoundingBox queries, a surface with a hole and an embedded point.
lc = 0.1;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {0.3, 0.3, 0, lc / 2}; Point(6) = {0.5, 0.3, 0, lc / 2}; Point(7) = {0.4, 0.5, 0, lc / 2};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7};
Plane Surface(1) = {1, 2};
Point(8) = {0.7, 0.7, 0, lc / 4};
Point{8} In Surface{1};
Printf("next tags: point %g, curve %g, surface %g, loop %g", newp, newc, news, newll);

ext[] = Extrude{0, 0, 0.5}{ Surface{1}; };
Printf("extrude: top %g, volume %g, %g sides", ext[0], ext[1], #ext[] - 2);
Printf("sides: %g %g %g %g %g %g %g", ext[{2:8}]);

copy[] = Duplicata{ Surface{1}; };
Printf("duplicata: %g", copy[0]);
Rotate{{0, 0, 1}, {0.5, 0.5, 0}, Pi / 4}{ Surface{copy[0]}; }
Translate{2, 0, 0}{ Surface{copy[0]}; }
bb[] = BoundingBox Surface{copy[0]};
Printf("moved box: %.6g %.6g %.6g %.6g %.6g %.6g", bb[0], bb[1], bb[2], bb[3], bb[4], bb[5]);

b[] = Boundary{ Surface{1}; };
Printf("boundary of 1: %g curves, first %g, last %g", #b[], b[0], b[#b[] - 1]);
cb[] = CombinedBoundary{ Volume{ext[1]}; };
Printf("combined boundary of the volume: %g surfaces", #cb[]);

rev[] = Extrude{{0, 1, 0}, {3, 0, 0}, Pi / 2}{ Curve{4}; };
Printf("revolve: %g %g %g %g", rev[0], rev[1], rev[2], rev[3]);

Physical Surface("plate") = {1};
Physical Surface("copy") = {copy[0]};
Physical Surface("revolved") = {rev[1]};
