// MeshAlgorithm Surface{..} = n overrides Mesh.Algorithm surface by surface: three squares
// in a row meshed with MeshAdapt, Delaunay and the default Frontal-Delaunay (around an
// embedded point), conforming on the curves they share.
lc = 0.05;
For i In {0:3}
  Point(i + 1) = {i, 0, 0, lc};
  Point(i + 5) = {i, 1, 0, lc};
  Line(i + 1) = {i + 1, i + 5};
EndFor
For i In {0:2}
  Line(i + 11) = {i + 1, i + 2};
  Line(i + 21) = {i + 6, i + 5};
  Curve Loop(i + 1) = {i + 11, i + 2, i + 21, -(i + 1)};
  Plane Surface(i + 1) = {i + 1};
EndFor
MeshAlgorithm Surface{1} = 1;
MeshAlgorithm Surface{2} = 5;
Point(9) = {2.5, 0.5, 0, lc};
Point{9} In Surface{3};
