// A disk of second-order triangles: curved boundary edges on the circle.
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 1};
Mesh.MeshSizeMax = 0.3;
Mesh.ElementOrder = 2;
