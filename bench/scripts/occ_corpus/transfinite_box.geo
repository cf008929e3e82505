// Fully structured hexahedral block: transfinite curves/surfaces/volume on an OCC Box.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 2, 0.5};
nx = 10; ny = 16; nz = 6;
// OCC box edges: 1..4 along z/y on x=0, etc.; pick by bounding box instead of guessing
ex() = Curve In BoundingBox{-0.01, -0.01, -0.01, 1.01, 0.01, 0.01};
ex() += Curve In BoundingBox{-0.01, 1.99, -0.01, 1.01, 2.01, 0.01};
ex() += Curve In BoundingBox{-0.01, -0.01, 0.49, 1.01, 0.01, 0.51};
ex() += Curve In BoundingBox{-0.01, 1.99, 0.49, 1.01, 2.01, 0.51};
ey() = Curve In BoundingBox{-0.01, -0.01, -0.01, 0.01, 2.01, 0.01};
ey() += Curve In BoundingBox{0.99, -0.01, -0.01, 1.01, 2.01, 0.01};
ey() += Curve In BoundingBox{-0.01, -0.01, 0.49, 0.01, 2.01, 0.51};
ey() += Curve In BoundingBox{0.99, -0.01, 0.49, 1.01, 2.01, 0.51};
ez() = Curve In BoundingBox{-0.01, -0.01, -0.01, 0.01, 0.01, 0.51};
ez() += Curve In BoundingBox{0.99, -0.01, -0.01, 1.01, 0.01, 0.51};
ez() += Curve In BoundingBox{-0.01, 1.99, -0.01, 0.01, 2.01, 0.51};
ez() += Curve In BoundingBox{0.99, 1.99, -0.01, 1.01, 2.01, 0.51};
Transfinite Curve{ex()} = nx;
Transfinite Curve{ey()} = ny;
Transfinite Curve{ez()} = nz;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{1};
Physical Volume("hexblock") = {1};
