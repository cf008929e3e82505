// Disk extruded with layers into a prism cylinder (triangles, no recombine).
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 1};
Mesh.MeshSizeMax = 0.15;
v[] = Extrude {0, 0, 0.8} { Surface{1}; Layers{8}; };
Physical Volume("puck") = {v[1]};
