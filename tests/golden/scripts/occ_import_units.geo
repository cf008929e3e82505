// Geometry.OCCTargetUnit and Geometry.OCCScaling: a 10 x 20 x 30 mm box read from a STEP file
// (written by geomesh, in millimetres) in metres and centimetres, then scaled.
SetFactory("OpenCASCADE");
Geometry.OCCTargetUnit = "M";
v() = ShapeFromFile("occ_box_mm.step");
b() = BoundingBox Volume{v(0)};
Printf("M: volume %g, box %g %g %g %g %g %g", v(0), b(0), b(1), b(2), b(3), b(4), b(5));
Geometry.OCCTargetUnit = "CM";
v() = ShapeFromFile("occ_box_mm.step");
b() = BoundingBox Volume{v(0)};
Printf("CM: volume %g, box %g %g %g %g %g %g", v(0), b(0), b(1), b(2), b(3), b(4), b(5));
Geometry.OCCScaling = 2;
v() = ShapeFromFile("occ_box_mm.step");
b() = BoundingBox Volume{v(0)};
Printf("CM x2: volume %g, box %g %g %g %g %g %g", v(0), b(0), b(1), b(2), b(3), b(4), b(5));
Geometry.OCCTargetUnit = "M";
Geometry.OCCScaling = 3;
v() = ShapeFromFile("occ_box_mm.step");
b() = BoundingBox Volume{v(0)};
Printf("M x3: volume %g, box %g %g %g %g %g %g", v(0), b(0), b(1), b(2), b(3), b(4), b(5));
