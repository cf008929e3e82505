// 2D channel with a quadrangle boundary layer on the lower wall and Recombine Surface: the
// layer keeps its columns, the rest of the surface is recombined into quadrangles.
lc = 0.05;
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc};
Point(3) = {1, 0.4, 0, lc};
Point(4) = {0, 0.4, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Field[1] = BoundaryLayer;
Field[1].CurvesList = {1};
Field[1].Size = 0.01;
Field[1].Ratio = 1.2;
Field[1].Thickness = 0.05;
Field[1].Quads = 1;
BoundaryLayer Field = 1;
Recombine Surface{1};
Physical Surface("fluid") = {1};
Physical Curve("wall") = {1};
