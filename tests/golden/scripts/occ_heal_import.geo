// Loose faces read with Geometry.OCCSewFaces and OCCMakeSolids: sewn into one closed shell,
// made a solid; the tags of what the healed model holds. Then the same faces read from a STEP
// file beside them, and a sphere's degenerated edges removed on import.
SetFactory("OpenCASCADE");

Macro Report
  v() = Volume{:}; s() = Surface{:}; c() = Curve{:}; p() = Point{:};
  Printf("step %g: %g volumes, %g surfaces, %g curves, %g points", step, #v(), #s(), #c(), #p());
  For i In {0:#v()-1}
    f() = Boundary{ Volume{v(i)}; };
    Printf("volume %g: %g faces, first %g, last %g", v(i), #f(), f(0), f(#f()-1));
  EndFor
  For i In {0:#s()-1}
    e() = Boundary{ Surface{s(i)}; };
    Printf("surface %g: %g curves: %g %g %g %g", s(i), #e(), e(0), e(1), e(2), e(3));
  EndFor
Return

Geometry.OCCSewFaces = 1;
Geometry.OCCMakeSolids = 1;
Merge "occ_loose_faces.brep";
step = 1; Call Report;

r() = ShapeFromFile("occ_loose_faces.step");
Printf("step read %g volume(s): %g", #r(), r(0));
b() = BoundingBox Volume{r(0)};
Printf("its box %g %g %g %g %g %g", b(0), b(1), b(2), b(3), b(4), b(5));
step = 2; Call Report;
