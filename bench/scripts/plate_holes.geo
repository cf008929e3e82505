// A 2 x 1 plate with 200 circular holes (a 20 x 10 grid), size 0.004 on the plate's edges
// and half that on the holes.
DefineConstant[ lc = 0.004, nx = 20, ny = 10, r = 0.02 ];
Point(1) = {0, 0, 0, lc};
Point(2) = {2, 0, 0, lc};
Point(3) = {2, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
loops[] = {1};
For i In {0:nx-1}
  For j In {0:ny-1}
    cx = (i + 0.5) * 2 / nx;
    cy = (j + 0.5) / ny;
    c = newp;
    Point(c) = {cx, cy, 0, lc / 2};
    Point(c + 1) = {cx + r, cy, 0, lc / 2};
    Point(c + 2) = {cx, cy + r, 0, lc / 2};
    Point(c + 3) = {cx - r, cy, 0, lc / 2};
    Point(c + 4) = {cx, cy - r, 0, lc / 2};
    a = newc;
    Circle(a) = {c + 1, c, c + 2};
    Circle(a + 1) = {c + 2, c, c + 3};
    Circle(a + 2) = {c + 3, c, c + 4};
    Circle(a + 3) = {c + 4, c, c + 1};
    l = newcl;
    Curve Loop(l) = {a, a + 1, a + 2, a + 3};
    loops[] += l;
  EndFor
EndFor
Plane Surface(1) = loops[];
