// A bent pipe: a disk swept along a wire made of a line and an arc (Extrude Using Wire).
SetFactory("OpenCASCADE");
r = 0.15;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 1};
Point(3) = {1, 0, 1};
Point(4) = {1, 0, 2};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Wire(1) = {1, 2};
Disk(1) = {0, 0, 0, r};
Extrude { Surface{1}; } Using Wire {1}
Mesh.MeshSizeMax = 0.05;
Physical Volume("pipe") = {1};
