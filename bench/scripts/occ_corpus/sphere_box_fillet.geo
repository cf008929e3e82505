// A rounded dice: a sphere intersected with a cube, the sharp edges of the result then filleted.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1.5};
Box(2) = {-1, -1, -1, 2, 2, 2};
v() = BooleanIntersection{ Volume{1}; Delete; }{ Volume{2}; Delete; };
s() = Boundary{ Volume{v(0)}; };
e() = Unique(Abs(Boundary{ Surface{s()}; }));
Printf("%g edges", #e());
f() = Fillet{v(0)}{e()}{0.08};
Mesh.MeshSizeMax = 0.12;
Physical Volume("dice") = f();
