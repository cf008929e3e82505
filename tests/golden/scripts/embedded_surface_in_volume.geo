// A square plate embedded in a box (OpenCASCADE): the tetrahedra take its triangles as faces,
// one tetrahedron on each side, and its finer size spreads into the volume around it.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Rectangle(7) = {0.2, 0.3, 0.45, 0.6, 0.4};
Surface{7} In Volume{1};
MeshSize{ PointsOf{ Surface{7}; } } = 0.05;
Mesh.MeshSizeMax = 0.15;
