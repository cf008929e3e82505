// A Cylinder field: small elements inside a cylinder whose axis stands across a square plate.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
// The axis runs from the centre (0.4, 0.6, 0) along (0, 0, 1) and back: half its length each
// way; the radius is 0.25.
Field[1] = Cylinder;
Field[1].XCenter = 0.4; Field[1].YCenter = 0.6; Field[1].ZCenter = 0;
Field[1].XAxis = 0; Field[1].YAxis = 0; Field[1].ZAxis = 1;
Field[1].Radius = 0.25;
Field[1].VIn = 0.03;
Field[1].VOut = 0.1;
Background Field = 1;
