// Two BoundaryLayer fields in one channel: a fine layer on the floor, a coarse one on the ceiling.
lc = 0.08;
Point(1) = {0, 0, 0, lc}; Point(2) = {2, 0, 0, lc}; Point(3) = {2, 0.5, 0, lc}; Point(4) = {0, 0.5, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Field[1] = BoundaryLayer; Field[1].CurvesList = {1}; Field[1].Size = 0.002; Field[1].Ratio = 1.3;
Field[1].Thickness = 0.04; Field[1].Quads = 1;
Field[2] = BoundaryLayer; Field[2].CurvesList = {3}; Field[2].Size = 0.01; Field[2].Ratio = 1.2;
Field[2].Thickness = 0.06; Field[2].Quads = 1;
BoundaryLayer Field = 1;
BoundaryLayer Field = 2;
