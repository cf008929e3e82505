// Reduced: a slender cylinder (radius 0.02) meshed with size 0.1; geomesh fails on its lateral surface.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 1, 0.02};
Mesh.MeshSizeMax = 0.1;
