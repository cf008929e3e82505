// A coil spring: a small disk swept along a helical Spline wire (three turns).
SetFactory("OpenCASCADE");
Rc = 0.5; pitch = 0.3; turns = 3; n = 24;
pts[] = {};
For i In {0:turns*n}
  th = 2*Pi*i/n;
  p = newp; Point(p) = {Rc*Cos(th), Rc*Sin(th), pitch*th/(2*Pi)};
  pts[] += p;
EndFor
Spline(1) = {pts[]};
Wire(1) = {1};
Disk(1) = {Rc, 0, 0, 0.06};
Rotate{ {1, 0, 0}, {Rc, 0, 0}, Pi/2 } { Surface{1}; }
Extrude { Surface{1}; } Using Wire {1}
Mesh.MeshSizeMax = 0.04;
Physical Volume("spring") = {1};
