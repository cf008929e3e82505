// An extruded-aluminium heat sink: a base plate with ten thin fins fused in one BooleanUnion.
SetFactory("OpenCASCADE");
W = 3; D = 2; tb = 0.2; tf = 0.06; hf = 1.0; n = 10;
Box(1) = {0, 0, 0, W, D, tb};
fins() = {};
For k In {0:n-1}
  x = 0.1 + k*(W - 0.2 - tf)/(n - 1);
  f = newv;
  Box(f) = {x, 0, tb, tf, D, hf};
  fins() += f;
EndFor
hs() = BooleanUnion{ Volume{1}; Delete; }{ Volume{fins()}; Delete; };
Mesh.MeshSizeMax = 0.1;
Mesh.MeshSizeMin = 0.03;
Physical Volume("sink") = {hs()};
Physical Surface("contact") = Surface In BoundingBox{-0.01, -0.01, -0.01, W+0.01, D+0.01, 0.01};
