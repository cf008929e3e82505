// Lofted vase-like transition duct through a circle, an ellipse and a smaller circle (ThruSections).
SetFactory("OpenCASCADE");
Circle(1) = {0, 0, 0, 0.5};
Curve Loop(1) = {1};
Ellipse(2) = {0, 0, 0.8, 0.6, 0.35};
Curve Loop(2) = {2};
Circle(3) = {0, 0, 1.5, 0.3};
Curve Loop(3) = {3};
ThruSections(1) = {1:3};
Mesh.MeshSizeMax = 0.08;
Physical Volume("duct") = {1};
