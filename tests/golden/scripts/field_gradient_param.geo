// Derived size fields: the norm of a MathEval's gradient, and a MathEval read at mapped points.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Field[1] = MathEval;
Field[1].F = "0.02*(x+1)^2 + 0.01*y";
Field[2] = Gradient;
Field[2].InField = 1;
Field[3] = MathEval;
Field[3].F = "0.02 + 0.1*x";
Field[4] = Param;
Field[4].InField = 3;
Field[4].FX = "1 - y";
Field[4].FY = "x";
Field[4].FZ = "z";
Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;
