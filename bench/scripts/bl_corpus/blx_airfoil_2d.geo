// 2D airfoil (NACA 0012, blunt trailing edge, spline sides): quadrangle layer along the normals, triangles to a far box, physical groups; run with -3.
t = 0.12;
n = 40;
lc = 0.02;
lcTE = 0.005;
lcFar = 0.5;

Macro HalfThickness
  yt = 5 * t * (0.2969 * Sqrt(xc) - 0.1260 * xc - 0.3516 * xc^2 + 0.2843 * xc^3 - 0.1015 * xc^4);
Return

le = newp;
Point(le) = {0, 0, 0, lc / 4};
upper[] = {};
lower[] = {};
For i In {1 : n}
  xc = 0.5 * (1 - Cos(Pi * i / n));
  Call HalfThickness;
  size = (i == n) ? lcTE : lc;
  p = newp;
  Point(p) = {xc, yt, 0, size};
  upper[] += p;
  p = newp;
  Point(p) = {xc, -yt, 0, size};
  lower[] += p;
EndFor
// lower side, base, upper side: counter-clockwise around the section, normals pointing away from it
base = newl;
Line(base) = {lower[n - 1], upper[n - 1]};
top = newl;
Spline(top) = {upper[{n - 1 : 0 : -1}], le};
bottom = newl;
Spline(bottom) = {le, lower[]};
section[] = {bottom, base, top};

out[] = Extrude { Curve{section[]}; Layers{ {1, 1, 1, 1, 1, 1, 1, 1}, {0.0004, 0.001, 0.0018, 0.003, 0.0046, 0.0068, 0.0098, 0.014} }; Recombine; };

layer[] = {out[1], out[5], out[9]};
p = newp;
Point(p) = {-2, -2, 0, lcFar};
Point(p + 1) = {4, -2, 0, lcFar};
Point(p + 2) = {4, 2, 0, lcFar};
Point(p + 3) = {-2, 2, 0, lcFar};
l = newl;
Line(l) = {p, p + 1};
Line(l + 1) = {p + 1, p + 2};
Line(l + 2) = {p + 2, p + 3};
Line(l + 3) = {p + 3, p};
cl = newcl;
Curve Loop(cl) = {l : l + 3};
Curve Loop(cl + 1) = {out[0], out[4], out[8]};
air = news;
Plane Surface(air) = {cl, cl + 1};

Physical Curve("airfoil", 1) = {section[]};
Physical Curve("inlet", 2) = {l + 3, l, l + 2};
Physical Curve("outlet", 3) = {l + 1};
Physical Surface("fluid", 4) = {layer[], air};
