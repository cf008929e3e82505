// Restrict keeps a field to the surfaces listed (and their boundaries); Max takes the larger
// of two sizes. Two squares side by side: a Box refines both sides of their common edge, but
// Restrict lets it act on the left square only; a Max with a constant keeps it above 0.03.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {2, 0, 0, 0.1};
Point(4) = {2, 1, 0, 0.1}; Point(5) = {1, 1, 0, 0.1}; Point(6) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 5}; Line(3) = {5, 6}; Line(4) = {6, 1};
Line(5) = {2, 3}; Line(6) = {3, 4}; Line(7) = {4, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Field[1] = Box;
Field[1].VIn = 0.01; Field[1].VOut = 0.1;
Field[1].XMin = 0.6; Field[1].XMax = 1.4; Field[1].YMin = 0; Field[1].YMax = 1;
Field[1].Thickness = 0.3;
Field[2] = Restrict;
Field[2].InField = 1;
Field[2].SurfacesList = {1};
Field[3] = MathEval;
Field[3].F = "0.03";
Field[4] = Max;
Field[4].FieldsList = {2, 3};
Background Field = 4;
