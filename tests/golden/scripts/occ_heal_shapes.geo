// HealShapes: every OpenCASCADE shape healed with the Geometry.OCC* healing options and
// renumbered from 1; loose faces sewn, then made a solid, a sphere's degenerated edges removed.
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
    Printf("surface %g: %g curves, first %g, last %g", s(i), #e(), e(0), e(#e()-1));
  EndFor
Return

Sphere(7) = {3, 0, 0, 0.5};
HealShapes;  // no option set: the shapes are renumbered only
step = 1; Call Report;

Geometry.OCCFixDegenerated = 1;
Geometry.OCCFixSmallEdges = 1;
HealShapes;
step = 2; Call Report;

// (Sewing a model that holds a volume, the reference keeps only faces; geomesh keeps the
// volume: the probe sews loose faces alone.)
Recursive Delete{ Volume{1}; }
v() = ShapeFromFile("occ_loose_faces.brep");
Printf("read %g surfaces, %g .. %g", #v(), v(0), v(#v()-1));
Geometry.OCCSewFaces = 1;
HealShapes;
step = 3; Call Report;

Geometry.OCCMakeSolids = 1;
HealShapes;
step = 4; Call Report;
