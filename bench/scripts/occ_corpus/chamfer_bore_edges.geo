// A bearing block with a through bore whose two circular rims are chamfered.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1.2, 1};
Cylinder(2) = {1, -0.1, 0.5, 0, 1.4, 0, 0.3};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
// the bore rims are the circles on the faces y = 0 and y = 1.2
r1() = Curve In BoundingBox{0.6, -0.01, 0.1, 1.4, 0.01, 0.9};
r2() = Curve In BoundingBox{0.6, 1.19, 0.1, 1.4, 1.21, 0.9};
s1() = Surface In BoundingBox{-0.01, -0.01, -0.01, 2.01, 0.01, 1.01};
s2() = Surface In BoundingBox{-0.01, 1.19, -0.01, 2.01, 1.21, 1.01};
c() = Chamfer{1}{r1(0), r2(0)}{s1(0), s2(0)}{0.08};
Mesh.MeshSizeMax = 0.1;
Physical Volume("block") = c();
