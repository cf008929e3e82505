// A sandwich of touching parts (plate, two spacers, cover) glued into one conformal mesh with Coherence.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 3, 1, 0.2};
Box(2) = {0.2, 0.2, 0.2, 0.6, 0.6, 0.5};
Box(3) = {2.2, 0.2, 0.2, 0.6, 0.6, 0.5};
Box(4) = {0, 0, 0.7, 3, 1, 0.2};
Cylinder(5) = {1.5, 0.5, 0.2, 0, 0, 0.5, 0.25};
Coherence;
v() = Volume{:};
Printf("%g volumes after Coherence", #v());
Mesh.MeshSizeMax = 0.1;
Physical Volume("plates") = {Volume In BoundingBox{-0.01, -0.01, -0.01, 3.01, 1.01, 0.21}, Volume In BoundingBox{-0.01, -0.01, 0.69, 3.01, 1.01, 0.91}};
Physical Volume("posts") = {Volume In BoundingBox{0.1, 0.1, 0.19, 2.9, 0.9, 0.71}};
