// A drive shaft with an O-ring groove (Torus subtracted) and a keyway (Box subtracted), smoothed mesh.
SetFactory("OpenCASCADE");
R = 0.3;
Cylinder(1) = {0, 0, 0, 0, 0, 2.5, R};
Torus(2) = {0, 0, 0.5, R, 0.06};
Box(3) = {-0.06, 0.2, 1.2, 0.12, 0.2, 0.9};
s() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; };
Mesh.MeshSizeMax = 0.06;
Mesh.Smoothing = 5;
Mesh.Optimize = 1;
Physical Volume("shaft") = {s()};
