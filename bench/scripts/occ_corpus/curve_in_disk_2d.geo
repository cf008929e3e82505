// 2D circular membrane with an embedded spline fibre and a polyline seam forced into the mesh (Curve In Surface).
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 1};
Point(20) = {-0.6, -0.2, 0, 0.02};
Point(21) = {-0.2, 0.2, 0, 0.02};
Point(22) = {0.2, -0.1, 0, 0.02};
Point(23) = {0.6, 0.3, 0, 0.02};
Spline(20) = {20:23};
Point(24) = {-0.3, -0.6, 0, 0.03};
Point(25) = {0.0, -0.45, 0, 0.03};
Point(26) = {0.35, -0.6, 0, 0.03};
Line(21) = {24, 25};
Line(22) = {25, 26};
Curve{20, 21, 22} In Surface{1};
Mesh.MeshSizeMax = 0.08;
Physical Surface("membrane") = {1};
Physical Curve("fibre") = {20};
Physical Curve("seam") = {21, 22};
