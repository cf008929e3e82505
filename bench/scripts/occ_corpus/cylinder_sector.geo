// A 120-degree sector of a thick cylinder (pie slice shaft segment).
SetFactory("OpenCASCADE");

R = 1.0;
H = 0.6;
angle = 2*Pi/3;
Cylinder(1) = {0, 0, 0, 0, 0, H, R, angle};

MeshSize{ PointsOf{ Volume{1}; } } = 0.07;

Physical Volume("sector") = {1};
