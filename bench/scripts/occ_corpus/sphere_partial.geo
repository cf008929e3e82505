// Upper hemisphere cut to a 270-degree wedge (partial latitude and longitude angles).
SetFactory("OpenCASCADE");
rad = 2;
Sphere(1) = {0, 0, 0, rad, 0, Pi/2, 3*Pi/2};
Mesh.MeshSizeMax = 0.2;
Physical Volume("dome") = {1};
