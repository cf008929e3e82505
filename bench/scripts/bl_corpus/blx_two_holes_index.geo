// 2D: two circular holes in a plate, each with its own quadrangle layer (Using Index[0], Using Index[1]), triangles between; run with -3.
lc = 0.03;
lcFar = 0.15;

// four counter-clockwise arcs of a circle of centre (cx, cy) and radius r; returns arcs[]
Macro CircleArcs
  c = newp;
  Point(c) = {cx, cy, 0, lc};
  Point(c + 1) = {cx + r, cy, 0, lc};
  Point(c + 2) = {cx, cy + r, 0, lc};
  Point(c + 3) = {cx - r, cy, 0, lc};
  Point(c + 4) = {cx, cy - r, 0, lc};
  a = newl;
  Circle(a) = {c + 1, c, c + 2};
  Circle(a + 1) = {c + 2, c, c + 3};
  Circle(a + 2) = {c + 3, c, c + 4};
  Circle(a + 3) = {c + 4, c, c + 1};
  arcs[] = {a : a + 3};
Return

cx = -0.6; cy = 0; r = 0.3;
Call CircleArcs;
holeA[] = arcs[];
cx = 0.6; cy = 0.1; r = 0.2;
Call CircleArcs;
holeB[] = arcs[];

outA[] = Extrude { Curve{holeA[]}; Layers{ {1, 1, 1}, {0.01, 0.025, 0.045} }; Using Index[0]; Recombine; };
outB[] = Extrude { Curve{holeB[]}; Layers{ {2, 2}, {0.02, 0.05} }; Using Index[1]; Recombine; };

p = newp;
Point(p) = {-1.5, -1, 0, lcFar};
Point(p + 1) = {1.5, -1, 0, lcFar};
Point(p + 2) = {1.5, 1, 0, lcFar};
Point(p + 3) = {-1.5, 1, 0, lcFar};
l = newl;
Line(l) = {p, p + 1};
Line(l + 1) = {p + 1, p + 2};
Line(l + 2) = {p + 2, p + 3};
Line(l + 3) = {p + 3, p};
cl = newcl;
Curve Loop(cl) = {l : l + 3};
Curve Loop(cl + 1) = {outA[0], outA[4], outA[8], outA[12]};
Curve Loop(cl + 2) = {outB[0], outB[4], outB[8], outB[12]};
plate = news;
Plane Surface(plate) = {cl, cl + 1, cl + 2};
