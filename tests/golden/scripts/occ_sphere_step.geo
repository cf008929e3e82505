// A sphere read from a STEP file: one face with a seam and two poles, meshed in 3D.
Merge "occ_sphere.step";
Mesh.MeshSizeMax = 0.2;
