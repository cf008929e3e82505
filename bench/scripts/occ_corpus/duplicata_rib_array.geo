// A ribbed panel: one rib box copied with Translate{..}{ Duplicata{..} } along the panel, then all fused.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 3, 1, 0.1};
Box(2) = {0.2, 0, 0.1, 0.08, 1, 0.3};
ribs() = {2};
For k In {1:5}
  c() = Translate{ 0.5*k, 0, 0 } { Duplicata{ Volume{2}; } };
  ribs() += c();
EndFor
Printf("%g ribs", #ribs());
p() = BooleanUnion{ Volume{1}; Delete; }{ Volume{ribs()}; Delete; };
Mesh.MeshSizeMax = 0.06;
Physical Volume("panel") = {p()};
