// Straight wing slab (NACA 0012 section with a blunt trailing edge, splines extruded in z), prism layer on its three walls; run with -3.
c = 1;      // chord
span = 0.4;
t = 0.12;   // thickness ratio
n = 30;     // points per side
lc = 0.06;
lcTE = 0.02;

// half-thickness of the section at x (chord fraction)
Macro HalfThickness
  yt = 5 * t * c * (0.2969 * Sqrt(xc) - 0.1260 * xc - 0.3516 * xc^2 + 0.2843 * xc^3 - 0.1015 * xc^4);
Return

le = newp;
Point(le) = {0, 0, 0, lc / 3};
upper[] = {};
lower[] = {};
For i In {1 : n}
  xc = 0.5 * (1 - Cos(Pi * i / n));  // cosine spacing, fine at both ends
  Call HalfThickness;
  size = (i == n) ? lcTE : lc;
  p = newp;
  Point(p) = {xc * c, yt, 0, size};
  upper[] += p;
  p = newp;
  Point(p) = {xc * c, -yt, 0, size};
  lower[] += p;
EndFor

// upper side from the trailing edge to the leading edge, lower side back, then the blunt base
sUp = newl;
Spline(sUp) = {upper[{n - 1 : 0 : -1}], le};
sLo = newl;
Spline(sLo) = {le, lower[]};
base = newl;
Line(base) = {lower[n - 1], upper[n - 1]};

walls[] = {};
For k In {0 : 2}
  cur = (k == 0) ? sUp : ((k == 1) ? sLo : base);
  e[] = Extrude {0, 0, span} { Curve{cur}; };
  walls[] += e[1];
EndFor

out[] = Extrude { Surface{walls[]}; Layers{ {1, 1, 1, 1, 1, 1}, {0.0005, 0.0013, 0.0025, 0.0045, 0.0075, 0.012} }; Recombine; };
