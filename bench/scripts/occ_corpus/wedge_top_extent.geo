// A trapezoidal dovetail key: Wedge with a top x-extent (ltx), a hole drilled through it.
SetFactory("OpenCASCADE");
Wedge(1) = {0, 0, 0, 2, 0.8, 1.2, 0.6};
Cylinder(2) = {0.5, -0.1, 0.4, 0, 1, 0, 0.15};
k() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 0.07;
Physical Volume("key") = {k()};
