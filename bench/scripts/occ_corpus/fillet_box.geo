// A block with its four vertical edges rounded by Fillet.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 0.6};
f() = Fillet{1}{1, 3, 5, 7}{0.2};
Mesh.MeshSizeMax = 0.08;
Physical Volume("rounded") = f();
