// Transfinite surfaces (triangles) on the faces of an OCC box, volume filled by Delaunay tets.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Transfinite Curve{:} = 9;
Transfinite Surface{1:6};
Mesh.Algorithm3D = 1;
Physical Volume("cube") = {1};
