// A plate whose top face carries embedded load points and a stiffener line, extruded to 3D.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 0.2};
top = 6;
Point(50) = {0.5, 0.5, 0.2, 0.02};
Point(51) = {1.5, 0.5, 0.2, 0.02};
Point(52) = {0.3, 0.2, 0.2, 0.05};
Point(53) = {1.7, 0.8, 0.2, 0.05};
Line(50) = {52, 53};
Point{50, 51} In Surface{top};
Curve{50} In Surface{top};
Mesh.MeshSizeMax = 0.1;
Mesh.Algorithm = 5;
Physical Volume("plate") = {1};
Physical Point("loads") = {50, 51};
