// An imported bracket part (STEP via Merge) meshed with curvature-based sizing.
SetFactory("OpenCASCADE");
Merge "../../../tests/golden/scripts/occ_bracket.step";
Mesh.MeshSizeMax = 0.12;
Mesh.MeshSizeFromCurvature = 12;
Physical Volume("bracket") = {1};
