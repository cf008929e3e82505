// A block with a cylindrical boss; the boss root circle and the block's top edges are filleted after the union.
SetFactory("OpenCASCADE");
Box(1) = {-1, -1, 0, 2, 2, 0.5};
Cylinder(2) = {0, 0, 0.5, 0, 0, 0.6, 0.4};
u() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };
// edges lying in the plane z = 0.5 (block top outline and boss root circle)
e() = Curve In BoundingBox{-1.1, -1.1, 0.49, 1.1, 1.1, 0.51};
Printf("%g edges to fillet", #e());
f() = Fillet{u(0)}{e()}{0.1};
Mesh.MeshSizeMax = 0.1;
Physical Volume("part") = f();
