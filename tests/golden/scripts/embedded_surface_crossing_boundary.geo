// A plate embedded in a box that reaches out through the box's side: its triangles cross the
// boundary's, and the tetrahedra cannot take both as faces.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Rectangle(7) = {0.5, 0.25, 0.5, 1, 0.5};
Surface{7} In Volume{1};
Mesh.MeshSizeMax = 0.2;
