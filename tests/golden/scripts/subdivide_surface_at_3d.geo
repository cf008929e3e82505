// A model of surfaces only, meshed with -3 and Mesh.SubdivisionAlgorithm = 1: the surfaces
// are split into quadrangles as with -2, since there is no volume to mesh.
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Point(3) = {1, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1:4} = 3;
Transfinite Surface{1};
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1;
