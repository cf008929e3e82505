// A hollow pipe tee: two outer cylinders fused, then the fused bores subtracted to leave a thin-walled junction.
SetFactory("OpenCASCADE");
Ro = 0.5; Ri = 0.4; ro = 0.35; ri = 0.27;
Cylinder(1) = {-2, 0, 0, 4, 0, 0, Ro};
Cylinder(2) = {0, 0, 0, 0, 1.6, 0, ro};
outer() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };
Cylinder(3) = {-2.1, 0, 0, 4.2, 0, 0, Ri};
Cylinder(4) = {0, 0, 0, 0, 1.7, 0, ri};
bore() = BooleanUnion{ Volume{3}; Delete; }{ Volume{4}; Delete; };
tee() = BooleanDifference{ Volume{outer()}; Delete; }{ Volume{bore()}; Delete; };
Mesh.MeshSizeMax = 0.06;
Physical Volume("tee") = {tee()};
