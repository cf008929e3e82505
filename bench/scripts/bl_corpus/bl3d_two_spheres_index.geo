// Two spheres in a box, each with its own layer (Using Index[0] and Using Index[1]), tetrahedra between, physical groups; run with -3.
lc = 0.12;
lcFar = 0.5;
L = 2;

// eight outward-facing patches of a sphere of centre (x, y, z) and radius r; returns patches[]
Macro SpherePatches
  c = newp;
  Point(c)     = {x, y, z, lc};
  Point(c + 1) = {x + r, y, z, lc};
  Point(c + 2) = {x, y + r, z, lc};
  Point(c + 3) = {x - r, y, z, lc};
  Point(c + 4) = {x, y - r, z, lc};
  Point(c + 5) = {x, y, z + r, lc};
  Point(c + 6) = {x, y, z - r, lc};
  k = newl;
  Circle(k)      = {c + 1, c, c + 2};
  Circle(k + 1)  = {c + 2, c, c + 3};
  Circle(k + 2)  = {c + 3, c, c + 4};
  Circle(k + 3)  = {c + 4, c, c + 1};
  Circle(k + 4)  = {c + 2, c, c + 5};
  Circle(k + 5)  = {c + 5, c, c + 4};
  Circle(k + 6)  = {c + 4, c, c + 6};
  Circle(k + 7)  = {c + 6, c, c + 2};
  Circle(k + 8)  = {c + 1, c, c + 6};
  Circle(k + 9)  = {c + 6, c, c + 3};
  Circle(k + 10) = {c + 3, c, c + 5};
  Circle(k + 11) = {c + 5, c, c + 1};
  loops[] = {k + 9, -(k + 7), -(k + 1),
             -(k + 6), -(k + 2), -(k + 9),
             -k, k + 8, k + 7,
             -(k + 4), k + 1, k + 10,
             k, k + 11, k + 4,
             -(k + 5), -(k + 10), k + 2,
             -(k + 8), -(k + 3), k + 6,
             k + 5, -(k + 11), k + 3};
  patches[] = {};
  For m In {0 : 7}
    cl = newcl;
    Curve Loop(cl) = {loops[3 * m], loops[3 * m + 1], loops[3 * m + 2]};
    s = news;
    Surface(s) = {cl};
    patches[] += s;
  EndFor
Return

x = -0.8; y = 0; z = 0; r = 0.4;
Call SpherePatches;
left[] = patches[];
x = 0.8; y = 0; z = 0; r = 0.5;
Call SpherePatches;
right[] = patches[];

// thin layer on the small sphere, thicker on the large one
outL[] = Extrude { Surface{left[]}; Layers{ {1, 1, 1}, {0.01, 0.025, 0.05} }; Using Index[0]; Recombine; };
outR[] = Extrude { Surface{right[]}; Layers{ {1, 1, 1, 1}, {0.01, 0.03, 0.06, 0.1} }; Using Index[1]; Recombine; };

layers[] = {};
For i In {0 : 7}
  layers[] += {outL[5 * i + 1], outR[5 * i + 1]};
EndFor

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
sides[] = {l, l + 1, l + 2, l + 3,
           l + 4, l + 5, l + 6, l + 7,
           l, l + 9, -(l + 4), -(l + 8),
           l + 1, l + 10, -(l + 5), -(l + 9),
           l + 2, l + 11, -(l + 6), -(l + 10),
           l + 3, l + 8, -(l + 7), -(l + 11)};
box[] = {};
For m In {0 : 5}
  cl = newcl;
  Curve Loop(cl) = {sides[4 * m], sides[4 * m + 1], sides[4 * m + 2], sides[4 * m + 3]};
  s = news;
  Plane Surface(s) = {cl};
  box[] += s;
EndFor

sl = newsl;
Surface Loop(sl) = {box[]};
Surface Loop(sl + 1) = {outL[0], outL[5], outL[10], outL[15], outL[20], outL[25], outL[30], outL[35]};
Surface Loop(sl + 2) = {outR[0], outR[5], outR[10], outR[15], outR[20], outR[25], outR[30], outR[35]};
v = newv;
Volume(v) = {sl, sl + 1, sl + 2};

Physical Surface("small", 1) = {left[]};
Physical Surface("large", 2) = {right[]};
Physical Surface("box", 3) = {box[]};
Physical Volume("layers", 4) = {layers[]};
Physical Volume("fluid", 5) = {v};
