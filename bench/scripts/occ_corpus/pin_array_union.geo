// A pin-fin cold plate: a base plate with a 4 x 3 array of round pins fused one by one in a For loop.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 4, 3, 0.3};
body = 1;
For i In {0:3}
  For j In {0:2}
    c = newv;
    Cylinder(c) = {0.5 + i, 0.5 + j, 0.3, 0, 0, 0.8, 0.18};
    r() = BooleanUnion{ Volume{body}; Delete; }{ Volume{c}; Delete; };
    body = r(0);
  EndFor
EndFor
Mesh.MeshSizeMax = 0.12;
Physical Volume("coldplate") = {body};
