// A plate with two countersunk screw holes: each a cylinder plus a Cone (two radii) subtracted.
SetFactory("OpenCASCADE");
t = 0.4;
Box(1) = {0, 0, 0, 3, 1.5, t};
tools() = {};
For k In {0:1}
  x = 0.8 + 1.4*k;
  c = newv; Cylinder(c) = {x, 0.75, -0.1, 0, 0, t + 0.2, 0.15};
  tools() += c;
  c = newv; Cone(c) = {x, 0.75, t - 0.15, 0, 0, 0.1501, 0.15, 0.3};
  tools() += c;
EndFor
p() = BooleanDifference{ Volume{1}; Delete; }{ Volume{tools()}; Delete; };
Mesh.MeshSizeMax = 0.1;
Mesh.MeshSizeFromCurvature = 20;
Physical Volume("plate") = {p()};
