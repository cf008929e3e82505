// A sphere read from STEP with ShapeFromFile and assigned a physical group by name.
SetFactory("OpenCASCADE");
v() = ShapeFromFile("../../../tests/golden/scripts/occ_sphere.step");
Mesh.MeshSizeMax = 0.12;
Physical Volume("ball") = {v()};
