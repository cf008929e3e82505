// Engine-block-like cube with two crossing cylindrical bores removed.
SetFactory("OpenCASCADE");
a = 2;
Box(1) = {-a/2, -a/2, -a/2, a, a, a};
Cylinder(2) = {-a, 0, 0, 2*a, 0, 0, 0.45};
Cylinder(3) = {0, -a, 0, 0, 2*a, 0, 0.3};
v() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; };
Printf("result volume %g", v(0));
Mesh.MeshSizeMax = 0.15;
Physical Volume("block") = v();
