// A housing shell made by subtraction without Delete, the tool and original removed afterwards with Recursive Delete.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1.5, 1};
Box(2) = {0.15, 0.15, 0.15, 1.7, 1.2, 1};
Cylinder(3) = {-0.1, 0.75, 0.5, 0.4, 0, 0, 0.2};
shell() = BooleanDifference{ Volume{1}; }{ Volume{2, 3}; };
Printf("shell volume %g", shell(0));
Recursive Delete { Volume{1, 2, 3}; }
v() = Volume{:};
Printf("%g volume(s) left", #v());
Mesh.MeshSizeMax = 0.07;
Physical Volume("housing") = {shell()};
