// A surface of revolution: a triangle whose slanted side is a (straight) Bezier curve, turned
// a full turn about the z axis. The solid is a ring: the Bezier side sweeps a frustum's side,
// the others a cylinder and an annulus, each closing on a seam.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.12;
Point(1) = {1, 0, 0};
Point(2) = {1.5, 0, 0.5};
Point(3) = {2, 0, 1};
Point(4) = {1, 0, 1};
Bezier(1) = {1, 2, 3};
Line(2) = {3, 4};
Line(3) = {4, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
ring() = Extrude{ {0, 0, 1}, {0, 0, 0}, 2 * Pi }{ Surface{1}; };
