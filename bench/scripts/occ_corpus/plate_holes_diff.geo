// A thick plate with a 3 x 2 grid of through holes (BooleanDifference with cylinders in a loop).
SetFactory("OpenCASCADE");
Lx = 6; Ly = 4; t = 0.5; rh = 0.4;
Box(1) = {0, 0, 0, Lx, Ly, t};
holes[] = {};
For i In {0:2}
  For j In {0:1}
    holes[] += newv;
    Cylinder(newv) = {1 + 2*i, 1 + 2*j, -0.1, 0, 0, t + 0.2, rh};
  EndFor
EndFor
BooleanDifference{ Volume{1}; Delete; }{ Volume{holes[]}; Delete; }
Mesh.MeshSizeMin = 0.05;
Mesh.MeshSizeMax = 0.25;
Mesh.MeshSizeFromCurvature = 12;
Physical Volume("plate") = {1};
