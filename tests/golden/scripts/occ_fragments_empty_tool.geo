// Three boxes made conformal by BooleanFragments with an empty tool block, `{}`: the usual way
// to glue many volumes. The physical groups take the pieces through a list indexed by a list.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.2;
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
Box(3) = {0.5, 0.25, 0.5, 1, 0.5, 1};
f() = BooleanFragments{ Volume{1, 2, 3}; Delete; }{};
Printf("pieces: %g", #f());
For i In {0:#f()-1}
  Printf("%g", f(i));
EndFor
rest() = f({1:#f()-1});
Printf("rest: %g from %g", #rest(), rest(0));
Physical Volume("first", 1) = {f(0)};
Physical Volume("others", 2) = {f({1:#f()-1})};
