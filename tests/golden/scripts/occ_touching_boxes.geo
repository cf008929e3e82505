// Two boxes side by side, made separately and never fragmented: the face x = 1 exists twice,
// so the tetrahedra of the two boxes are not connected there. The volume mesher warns, naming
// both volumes and both surfaces, and meshes each box as asked.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
Mesh.MeshSizeMax = 0.3;
