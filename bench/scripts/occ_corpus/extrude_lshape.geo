// L-shaped bracket profile (union of two rectangles) extruded into a solid.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 2, 0.4};
Rectangle(2) = {0, 0, 0, 0.4, 1.5};
BooleanUnion(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
ext[] = Extrude {0, 0, 1} { Surface{3}; };
Mesh.MeshSizeMax = 0.1;
Physical Volume("bracket") = {ext[1]};
Physical Surface("base") = {3};
Physical Surface("cap") = {ext[0]};
