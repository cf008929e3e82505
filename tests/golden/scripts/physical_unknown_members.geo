// A physical group naming entities the model does not have keeps the others; each unknown
// member is reported once, however often the model is synchronized.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Surface("walls") = {1, 2, 99};
Physical Volume(5) = {1, 7};
n = #Surface{:};  // a query synchronizes the model
Printf("%g surfaces", n);
Mesh.MeshSizeMax = 0.5;
