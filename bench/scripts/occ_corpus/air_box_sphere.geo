// An electrostatics model: a conducting ball and a dielectric slab inside an air box, glued by BooleanFragments.
SetFactory("OpenCASCADE");
Box(1) = {-2, -2, -2, 4, 4, 4};
Sphere(2) = {0, 0, 0.6, 0.4};
Box(3) = {-1, -1, -0.6, 2, 2, 0.3};
all() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; };
Printf("%g volumes", #all());
air() = Volume In BoundingBox{-2.01, -2.01, -2.01, 2.01, 2.01, 2.01};
air() -= {2, 3};
MeshSize{ PointsOf{ Volume{air()}; } } = 0.5;
MeshSize{ PointsOf{ Volume{2, 3}; } } = 0.08;
Physical Volume("ball") = {2};
Physical Volume("slab") = {3};
Physical Volume("air") = {air()};
Physical Surface("infinity") = Surface In BoundingBox{-2.01, -2.01, -2.01, 2.01, 2.01, -1.99};
Physical Surface("ball_skin") = Boundary{ Volume{2}; };
