// ExternalProcess is refused (geomesh does not run external programs): the field reads 1e22,
// so the Min below is the sizes of the Ball alone.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Field[1] = ExternalProcess;
Field[1].CommandLine = "python3 sizes.py";
Field[2] = Ball;
Field[2].Radius = 0.2; Field[2].XCenter = 0.5; Field[2].YCenter = 0.5;
Field[2].VIn = 0.03; Field[2].VOut = 0.1; Field[2].Thickness = 0.2;
Field[3] = Min;
Field[3].FieldsList = {1, 2};
Background Field = 3;
