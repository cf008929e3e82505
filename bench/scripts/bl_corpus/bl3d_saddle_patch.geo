// Curved four-sided patch (Coons surface on four splines of a saddle), prism layer along its normals; run with -3.
lc = 0.06;
m = 8;  // points per edge spline
Macro Saddle
  zs = 0.3 * (xs * xs - ys * ys);
Return

corners[] = {-1, -1, 1, -1, 1, 1, -1, 1};
edges[] = {};
For k In {0 : 3}
  x0 = corners[2 * k];
  y0 = corners[2 * k + 1];
  x1 = corners[(2 * k + 2) % 8];
  y1 = corners[(2 * k + 3) % 8];
  pts[] = {};
  For i In {0 : m}
    If ((k > 0 && i == 0) || (k == 3 && i == m))
      // reuse the corner already made by the previous edge (or the first corner)
      pts[] += (i == 0) ? last : first;
    Else
      xs = x0 + (x1 - x0) * i / m;
      ys = y0 + (y1 - y0) * i / m;
      Call Saddle;
      p = newp;
      Point(p) = {xs, ys, zs, lc};
      pts[] += p;
    EndIf
  EndFor
  If (k == 0)
    first = pts[0];
  EndIf
  last = pts[m];
  s = newl;
  Spline(s) = {pts[]};
  edges[] += s;
EndFor
Curve Loop(1) = {edges[]};
Surface(1) = {1};

out[] = Extrude { Surface{1}; Layers{ {2, 2, 2}, {0.01, 0.03, 0.08} }; Recombine; };
