// A channel block with a cross bore; boundary groups made from Abs(Boundary{Volume}) minus faces found by bounding box.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 4, 1, 1};
Cylinder(2) = {2, -0.1, 0.5, 0, 1.2, 0, 0.3};
v() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
eps = 1e-3;
inlet() = Surface In BoundingBox{-eps, -eps, -eps, eps, 1+eps, 1+eps};
outlet() = Surface In BoundingBox{4-eps, -eps, -eps, 4+eps, 1+eps, 1+eps};
bore() = Surface In BoundingBox{1.7-eps, -eps, 0.2-eps, 2.3+eps, 1+eps, 0.8+eps};
walls() = Abs(Boundary{ Volume{v()}; });
walls() -= {inlet(), outlet(), bore()};
Printf("%g wall faces", #walls());
Mesh.MeshSizeMax = 0.1;
Physical Surface("inlet") = {inlet()};
Physical Surface("outlet") = {outlet()};
Physical Surface("bore") = {bore()};
Physical Surface("walls") = {walls()};
Physical Volume("solid") = {v()};
