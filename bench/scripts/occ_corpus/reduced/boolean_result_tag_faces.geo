// Reduced: with an explicit result tag, geomesh renumbers the untouched faces of the object.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 2, 2};
Sphere(2) = {1, 1, 1, 0.5};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 0.3;
Physical Surface("bottom") = {5};
Physical Volume("solid") = {3};
