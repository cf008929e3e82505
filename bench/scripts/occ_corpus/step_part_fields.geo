// A merged STEP part refined near its curved edges with a Distance + Threshold field.
SetFactory("OpenCASCADE");
Merge "../../../tutorials/part.step";
Field[1] = Distance;
Field[1].CurvesList = {Curve{:}};
Field[1].Sampling = 50;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.03;
Field[2].SizeMax = 0.15;
Field[2].DistMin = 0.02;
Field[2].DistMax = 0.3;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Physical Volume("part") = {1};
