// 2D plate with four holes, refined around the hole rims by a Distance/Threshold field on their curves.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 4, 2};
For k In {0:3}
  Disk(10 + k) = {0.6 + k*0.93, 1 + 0.3*(-1)^k, 0, 0.18};
EndFor
BooleanDifference{ Surface{1}; Delete; }{ Surface{10:13}; Delete; }
// hole rims: every curve not on the outer rectangle
all() = Abs(Boundary{ Surface{1}; });
outer() = Curve In BoundingBox{-0.01, -0.01, -0.01, 4.01, 0.01, 0.01};
outer() += Curve In BoundingBox{-0.01, 1.99, -0.01, 4.01, 2.01, 0.01};
outer() += Curve In BoundingBox{-0.01, -0.01, -0.01, 0.01, 2.01, 0.01};
outer() += Curve In BoundingBox{3.99, -0.01, -0.01, 4.01, 2.01, 0.01};
rims() = all();
rims() -= outer();
Field[1] = Distance;
Field[1].CurvesList = {rims()};
Field[1].Sampling = 100;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.015;
Field[2].SizeMax = 0.12;
Field[2].DistMin = 0.02;
Field[2].DistMax = 0.5;
Background Field = 2;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Physical Surface("plate") = {1};
Physical Curve("holes") = {rims()};
