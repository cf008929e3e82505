// A box with mesh refinement near one of its edges using Distance + Threshold fields on an OCC curve.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Field[1] = Distance;
Field[1].CurvesList = {1};
Field[1].Sampling = 40;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.02;
Field[2].SizeMax = 0.12;
Field[2].DistMin = 0.05;
Field[2].DistMax = 0.4;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Volume("domain") = {1};
