// A round flange with a central bore and six bolt holes cut one at a time inside a For loop.
SetFactory("OpenCASCADE");
Ro = 1.5; Rb = 1.1; rh = 0.12; t = 0.25;
Cylinder(1) = {0, 0, 0, 0, 0, t, Ro};
Cylinder(2) = {0, 0, -0.1, 0, 0, t + 0.2, 0.5};
flange() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
For k In {0:5}
  th = k * 2*Pi/6;
  h = newv;
  Cylinder(h) = {Rb*Cos(th), Rb*Sin(th), -0.1, 0, 0, t + 0.2, rh};
  flange() = BooleanDifference{ Volume{flange(0)}; Delete; }{ Volume{h}; Delete; };
EndFor
Mesh.MeshSizeMax = 0.1;
Mesh.MeshSizeFromCurvature = 16;
Physical Volume("flange") = {flange(0)};
