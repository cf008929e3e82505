// The older periodicity form on OpenCASCADE surfaces: the box's face at x = 1 listed against
// the one at x = 0 by their curves; the translation follows from them.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Periodic Surface 2 {5, 8, 7, 6} = 1 {1, 4, 3, 2};
Mesh.MeshSizeMax = 0.3;
