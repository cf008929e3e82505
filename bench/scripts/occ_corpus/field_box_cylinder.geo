// Flow domain around a cylinder with a Box refinement field in the wake, combined with Min.
SetFactory("OpenCASCADE");
Box(1) = {-1, -1, 0, 4, 2, 0.5};
Cylinder(2) = {0, 0, -0.1, 0, 0, 0.7, 0.2};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Field[1] = Box;
Field[1].VIn = 0.06;
Field[1].VOut = 0.2;
Field[1].XMin = 0.1; Field[1].XMax = 2.5;
Field[1].YMin = -0.4; Field[1].YMax = 0.4;
Field[1].ZMin = -1; Field[1].ZMax = 1;
Field[1].Thickness = 0.3;
Field[2] = MathEval;
Field[2].F = "0.2";
Field[3] = Min;
Field[3].FieldsList = {1, 2};
Background Field = 3;
Physical Volume("fluid") = {1};
Physical Surface("cylinder") = {7};
