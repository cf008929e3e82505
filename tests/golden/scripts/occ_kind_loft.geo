// A B-spline surface: a smooth loft through two equal circles one above the other, which is
// exactly a cylinder's side (radius 0.8, height 1.5), capped into a solid.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.1;
Circle(1) = {0, 0, 0, 0.8};
Circle(2) = {0, 0, 1.5, 0.8};
Curve Loop(1) = {1};
Curve Loop(2) = {2};
ThruSections(1) = {1, 2};
