// A bracket assembly placed with Translate, Rotate, Dilate and Symmetry of OCC volumes, then made conformal by fragments.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 0.3};
// a rib: box rotated 90 degrees about z and moved onto the plate
Box(2) = {0, 0, 0, 1, 0.2, 0.6};
Rotate{ {0, 0, 1}, {0, 0, 0}, Pi/2 } { Volume{2}; }
Translate{ 0.8, 0.1, 0.3 } { Volume{2}; }
// a boss scaled up from a unit cylinder
Cylinder(3) = {0, 0, 0, 0, 0, 1, 0.5};
Dilate{ {0, 0, 0}, {0.5, 0.5, 0.4} } { Volume{3}; }
Translate{ 1.5, 0.5, 0.3 } { Volume{3}; }
// mirror copy of the boss on the other side of x = 1
b() = Symmetry{ 1, 0, 0, -1 } { Duplicata{ Volume{3}; } };
Printf("mirrored boss %g", b(0));
f() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2, 3, b(0)}; Delete; };
Printf("%g fragments", #f());
Mesh.MeshSizeMax = 0.08;
Physical Volume("assembly") = {f()};
