// A twisted prism made with Ruled ThruSections through three square wires.
SetFactory("OpenCASCADE");
n = 3;
For k In {0:n-1}
  ang = k * Pi/8;
  z = k * 0.6;
  p0 = newp; Point(p0) = {Cos(ang), Sin(ang), z};
  p1 = newp; Point(p1) = {-Sin(ang), Cos(ang), z};
  p2 = newp; Point(p2) = {-Cos(ang), -Sin(ang), z};
  p3 = newp; Point(p3) = {Sin(ang), -Cos(ang), z};
  l0 = newl; Line(l0) = {p0, p1};
  l1 = newl; Line(l1) = {p1, p2};
  l2 = newl; Line(l2) = {p2, p3};
  l3 = newl; Line(l3) = {p3, p0};
  Curve Loop(k+1) = {l0, l1, l2, l3};
EndFor
Ruled ThruSections(1) = {1:n};
Mesh.MeshSizeMax = 0.12;
Physical Volume("twisted") = {1};
