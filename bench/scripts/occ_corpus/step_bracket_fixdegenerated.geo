// An imported bracket with healing options on, a bolt hole drilled after import and the faces grouped by bounding box.
SetFactory("OpenCASCADE");
Geometry.OCCFixDegenerated = 1;
Geometry.OCCFixSmallFaces = 1;
Geometry.Tolerance = 1e-5;
v() = ShapeFromFile("../../../tests/golden/scripts/occ_bracket.step");
b() = BoundingBox Volume{v(0)};
Printf("bracket box %g %g %g  %g %g %g", b(0), b(1), b(2), b(3), b(4), b(5));
Cylinder(100) = {2, 1.5, -0.1, 0, 0, 0.7, 0.15};
r() = BooleanDifference{ Volume{v(0)}; Delete; }{ Volume{100}; Delete; };
Mesh.MeshSizeMax = 0.12;
Physical Volume("bracket") = {r()};
Physical Surface("base") = Surface In BoundingBox{-0.01, -0.01, -0.01, 4.01, 2.01, 0.01};
Physical Surface("end") = Surface In BoundingBox{3.99, -0.01, -0.01, 4.01, 2.01, 0.51};
Physical Surface("new_hole") = Surface In BoundingBox{1.8, 1.3, -0.01, 2.2, 1.7, 0.51};
