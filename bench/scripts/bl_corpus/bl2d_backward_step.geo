// Backward-facing step: a quadrangle boundary layer along the lower walls, a fan of 6
// elements at the step's convex edge, one bisector column at its concave foot.
lc = 0.08; lw = 0.03;
Point(1) = {0, 0.2, 0, lw};
Point(2) = {0.6, 0.2, 0, lw};
Point(3) = {0.6, 0, 0, lw};
Point(4) = {2.5, 0, 0, lc};
Point(5) = {2.5, 0.6, 0, lc};
Point(6) = {0, 0.6, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Field[1] = BoundaryLayer;
Field[1].CurvesList = {1, 2, 3};
Field[1].Size = 0.002;
Field[1].Ratio = 1.25;
Field[1].Thickness = 0.025;
Field[1].Quads = 1;
Field[1].FanPointsList = {2};
Field[1].FanPointsSizesList = {6};
BoundaryLayer Field = 1;
