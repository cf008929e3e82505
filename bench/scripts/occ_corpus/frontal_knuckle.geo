// A knuckle joint eye: a slab with a rounded end (union with a cylinder) and a pin hole, meshed with the Frontal 3D algorithm.
SetFactory("OpenCASCADE");
Box(1) = {0, -0.5, 0, 2, 1, 0.4};
Cylinder(2) = {2, 0, 0, 0, 0, 0.4, 0.5};
Cylinder(3) = {2, 0, -0.1, 0, 0, 0.6, 0.25};
u() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };
eye() = BooleanDifference{ Volume{u()}; Delete; }{ Volume{3}; Delete; };
Mesh.Algorithm3D = 4;
Mesh.Algorithm = 6;
Mesh.MeshSizeMax = 0.08;
Physical Volume("eye") = {eye()};
