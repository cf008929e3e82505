// An Extend size field: the boundary's edge lengths (0.02 at one corner, 0.1 elsewhere) carried
// into the square over DistMax = 0.3, growing to SizeMax = 0.2 beyond.
Point(1) = {0, 0, 0, 0.02}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh.MeshSizeExtendFromBoundary = 0;
Field[1] = Extend;
Field[1].CurvesList = {1, 2, 3, 4};
Field[1].DistMax = 0.3;
Field[1].SizeMax = 0.2;
Field[1].Power = 1;
Background Field = 1;
