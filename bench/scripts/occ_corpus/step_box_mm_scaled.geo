// A millimetre STEP block imported, with a hole cut through it after import.
SetFactory("OpenCASCADE");
Geometry.OCCTargetUnit = "MM";
a() = ShapeFromFile("../../../tests/golden/scripts/occ_box_mm.step");
Cylinder(100) = {5, 10, -1, 0, 0, 32, 3};
BooleanDifference{ Volume{a()}; Delete; }{ Volume{100}; Delete; }
Mesh.MeshSizeMax = 1.5;
Physical Volume("block") = {1};
