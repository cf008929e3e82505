// A curved coolant channel: an off-axis disk revolved a half turn about z with layers (prisms), plus a straight inlet.
SetFactory("OpenCASCADE");
Disk(1) = {1.2, 0, 0, 0.25};
Rotate{ {1, 0, 0}, {1.2, 0, 0}, Pi/2 } { Surface{1}; }
Mesh.MeshSizeMax = 0.07;
a[] = Extrude{ {0, 0, 1}, {0, 0, 0}, Pi } { Surface{1}; Layers{24}; };
b[] = Extrude{ 0, -0.8, 0 } { Surface{1}; Layers{8}; };
Printf("bend %g, inlet %g", a[1], b[1]);
Physical Volume("bend") = {a[1]};
Physical Volume("inlet") = {b[1]};
