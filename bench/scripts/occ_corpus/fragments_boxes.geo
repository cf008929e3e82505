// Multi-material stack: three touching/overlapping boxes made conformal by BooleanFragments.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
Box(3) = {0.5, 0.25, 0.5, 1, 0.5, 1};
f() = BooleanFragments{ Volume{1, 2, 3}; Delete; }{};
Printf("fragments: %g volumes", #f());
Mesh.MeshSizeMax = 0.1;
Physical Volume("left") = {f(0)};
Physical Volume("rest") = {f({1:#f()-1})};
