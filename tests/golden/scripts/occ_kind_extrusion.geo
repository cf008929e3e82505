// Surfaces of linear extrusion: a closed periodic B-spline profile (an ellipse-like curve)
// swept 2 along z makes a tube; with its end faces, a solid.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.1;
Ellipse(1) = {0, 0, 0, 1, 0.6};
Curve Loop(1) = {1};
Plane Surface(1) = {1};
Extrude{0, 0, 2}{ Surface{1}; }
