// Reduced: a cube with all 12 edges filleted with a radius (0.08) below the size (0.12); geomesh refines round the fillets and on the faces, Gmsh does not.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 2, 2};
Fillet{1}{1:12}{0.08}
Mesh.MeshSizeMax = 0.12;
