// Reduced: a sphere squashed by a non-uniform Dilate (a B-spline surface with poles) and curvature sizing; geomesh asks >1e9 segments on the seam.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Dilate{ {0, 0, 0}, {1, 1, 0.5} } { Volume{1}; }
Mesh.MeshSizeFromCurvature = 16;
