// A perforated plate meshed with hexahedra: recombined OCC face with three holes extruded with Layers.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 3, 1};
Disk(2) = {0.5, 0.5, 0, 0.2};
Disk(3) = {1.5, 0.5, 0, 0.25};
Disk(4) = {2.5, 0.5, 0, 0.2};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2:4}; Delete; }
Mesh.MeshSizeMax = 0.07;
Recombine Surface{1};
out[] = Extrude {0, 0, 0.2} { Surface{1}; Layers{4}; Recombine; };
Physical Volume("plate") = {out[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {out[0]};
