// A Frustum size field along the middle of a square: fine near its axis, 0.02 at one end and
// 0.04 at the other, growing to 0.1 at its outer radius (0.3, then 0.5).
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Field[1] = Frustum;
Field[1].X1 = 0; Field[1].Y1 = 0.5; Field[1].Z1 = 0;
Field[1].X2 = 1; Field[1].Y2 = 0.5; Field[1].Z2 = 0;
Field[1].InnerR1 = 0; Field[1].OuterR1 = 0.3;
Field[1].InnerR2 = 0; Field[1].OuterR2 = 0.5;
Field[1].InnerV1 = 0.02; Field[1].OuterV1 = 0.1;
Field[1].InnerV2 = 0.04; Field[1].OuterV2 = 0.1;
Background Field = 1;
