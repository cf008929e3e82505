// Layered soil column: boxes stacked in a loop and glued with BooleanFragments, one group per layer.
SetFactory("OpenCASCADE");
N = 3;
t[] = {0.4, 0.7, 0.5};
z = 0;
For k In {0:N-1}
  Box(k+1) = {0, 0, z, 2, 2, t[k]};
  z += t[k];
EndFor
BooleanFragments{ Volume{1:N}; Delete; }{}
Mesh.MeshSizeMax = 0.15;
For k In {1:N}
  Physical Volume(Sprintf("layer_%g", k)) = {k};
EndFor
