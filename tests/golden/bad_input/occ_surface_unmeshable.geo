// Mesh.Algorithm 3 keeps only the boundary nodes: a sphere's face cannot be covered by them.
SetFactory("OpenCASCADE");
Mesh.Algorithm = 3;
Mesh.MeshSizeMax = 0.1;
Sphere(1) = {0, 0, 0, 1};
