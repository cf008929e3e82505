// Reduced: a rectangle embedded in a box with Surface In Volume; geomesh's tetrahedra ignore it (nodes 0.58x, no conformity).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Rectangle(10) = {0.5, 0.25, 0.5, 1, 0.5};
Surface{10} In Volume{1};
MeshSize{ PointsOf{ Surface{10}; } } = 0.04;
Mesh.MeshSizeMax = 0.12;
