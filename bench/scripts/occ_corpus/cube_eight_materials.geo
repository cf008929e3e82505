// A multi-material cube split into 8 sub-cubes by fragments with three half-size boxes, one physical volume per octant.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 2, 2};
// three cutting boxes: the halves x < 1, y < 1, z < 1
Box(2) = {0, 0, 0, 1, 2, 2};
Box(3) = {0, 0, 0, 2, 1, 2};
Box(4) = {0, 0, 0, 2, 2, 1};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2:4}; Delete; }
v() = Volume{:};
Printf("%g sub-cubes", #v());
Mesh.MeshSizeMax = 0.15;
For i In {0:1}
  For j In {0:1}
    For k In {0:1}
      oct() = Volume In BoundingBox{i - 0.01, j - 0.01, k - 0.01, i + 1.01, j + 1.01, k + 1.01};
      Physical Volume(Sprintf("mat_%g%g%g", i, j, k)) = {oct()};
    EndFor
  EndFor
EndFor
