// Hex-dominant slab: recombined quad base (MeshAdapt) extruded with layers into hexahedra.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 3, 1, 0.3};
Mesh.Algorithm = 1;
MeshSize{ PointsOf{ Surface{1}; } } = 0.1;
Recombine Surface{1};
Extrude {0, 0, 0.4} { Surface{1}; Layers{4}; Recombine; }
Physical Volume("slab") = {1};
