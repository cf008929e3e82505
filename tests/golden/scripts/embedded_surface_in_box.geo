// A rectangle embedded in a 2 x 1 x 1 box, finer than the box (the occ_corpus reduced case
// surface_in_volume): the tetrahedra use every node of the rectangle.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Rectangle(10) = {0.5, 0.25, 0.5, 1, 0.5};
Surface{10} In Volume{1};
MeshSize{ PointsOf{ Surface{10}; } } = 0.04;
Mesh.MeshSizeMax = 0.12;
