// Transformations and extrusions returning tags, and boundaries of what they build.
lc = 0.5;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
copy[] = Translate {2, 0, 0} { Duplicata { Surface{1}; } };
Printf("copy: surface %g", copy[0]);
out[] = Extrude {0, 0, 1} { Surface{1}; };
Printf("extrude gave %g entities: top %g, volume %g", #out[], out[0], out[1]);
Printf("lateral surfaces %g %g %g %g", out[2], out[3], out[4], out[5]);
sides[] = Boundary{ Volume{out[1]}; };
Printf("volume boundary: %g surfaces", #sides[]);
outer[] = CombinedBoundary{ Surface{1, copy[0]}; };
Printf("combined boundary of the two squares: %g curves", #outer[]);
ends[] = Boundary{ Curve{1}; };
Printf("curve 1 from %g to %g", ends[0], ends[1]);
p9 = newp;
Point(p9) = {3, 0, 0, lc};
Rotate {{0, 0, 1}, {0, 0, 0}, Pi / 2} { Point{p9}; }
p[] = Point{p9};
Printf("rotated point: x is zero %g, y %g, z %g", Fabs(p[0]) < 1e-12, p[1], p[2]);
p20 = newp;
Point(p20) = {1, 1, 1, lc};
Dilate {{0, 0, 0}, 2} { Point{p20}; }
q[] = Point{p20};
Printf("dilated new point: %g %g %g", q[0], q[1], q[2]);
Printf("next surface %g, next volume %g", news, newv);
