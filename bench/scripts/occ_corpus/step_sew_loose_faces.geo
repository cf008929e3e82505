// A cube exported as six unsewn faces: STEP merged with face sewing, solid making and a healing tolerance.
SetFactory("OpenCASCADE");
Geometry.Tolerance = 1e-6;
Geometry.OCCFixDegenerated = 1;
Geometry.OCCFixSmallEdges = 1;
Geometry.OCCSewFaces = 1;
Geometry.OCCMakeSolids = 1;
Merge "../../../tests/golden/scripts/occ_loose_faces.step";
v() = Volume{:};
Printf("%g volume(s) after healing", #v());
Mesh.MeshSizeMax = 0.07;
Physical Volume("cube") = {v()};
Physical Surface("skin") = Abs(Boundary{ Volume{v()}; });
