// A cylinder in a channel with a quadrangle boundary layer round the cylinder and on the
// lower wall, the field named by an expression and twice (kept once), its older option names.
lc = 0.1;
Point(1) = {0, 0, 0, lc};
Point(2) = {2, 0, 0, lc};
Point(3) = {2, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Point(5) = {0.6, 0.5, 0, 0.02};
Point(6) = {0.75, 0.5, 0, 0.02};
Point(7) = {0.45, 0.5, 0, 0.02};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6};
Plane Surface(1) = {1, 2};
f = 3;
Field[f] = BoundaryLayer;
Field[f].EdgesList = {1, 5, 6};
Field[f].hwall_n = 0.004;
Field[f].Ratio = 1.2;
Field[f].Thickness = 0.03;
Field[f].Quads = 1;
BoundaryLayer Field = f;
BoundaryLayer Field = 1 + 2;
