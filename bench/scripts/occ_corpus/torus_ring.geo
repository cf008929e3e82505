// A doughnut-shaped O-ring (full torus).
SetFactory("OpenCASCADE");
Rmaj = 1.5;
rmin = 0.35;
Torus(1) = {0, 0, 0, Rmaj, rmin};
Mesh.MeshSizeMax = rmin / 3;
Mesh.Algorithm3D = 10;
Physical Volume("oring") = {1};
