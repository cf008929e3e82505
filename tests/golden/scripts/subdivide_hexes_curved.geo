// Mesh.SubdivisionAlgorithm = 2 on curved parts: the middles of the segments of circles and
// the centres of the triangles on the cylinder's side and the sphere are put on them.
SetFactory("OpenCASCADE");
Mesh.SubdivisionAlgorithm = 2;
Cylinder(1) = {0, 0, 0, 0, 0, 1, 0.5};
Sphere(2) = {2, 0, 0, 0.5};
Mesh.MeshSizeMax = 0.2;
