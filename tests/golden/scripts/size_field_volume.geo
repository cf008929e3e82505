// A size field followed inside a volume: fine around a point at the centre of a cube, coarse
// away from it, with sizes not extended from the boundary.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Point(100) = {0.5, 0.5, 0.5};
Field[1] = Distance;
Field[1].PointsList = {100};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.03;
Field[2].SizeMax = 0.2;
Field[2].DistMin = 0.1;
Field[2].DistMax = 0.4;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
