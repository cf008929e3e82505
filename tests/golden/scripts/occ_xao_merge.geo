// Merge of an XAO file written by the reference (its -0 output for a filleted, bored block):
// the entities get the tags the reference gives them.
SetFactory("OpenCASCADE");
Merge "occ_reference_part.xao";
v() = Volume{:}; s() = Surface{:}; c() = Curve{:}; p() = Point{:};
Printf("model: %g volumes, %g surfaces, %g curves, %g points; last %g %g %g %g", #v(), #s(),
       #c(), #p(), v(#v()-1), s(#s()-1), c(#c()-1), p(#p()-1));
f() = Boundary{ Volume{v(0)}; };
Printf("volume %g: %g faces: %g %g %g ... %g", v(0), #f(), f(0), f(1), f(2), f(#f()-1));
For i In {0:#s()-1:3}
  e() = Boundary{ Surface{s(i)}; };
  Printf("surface %g: %g curves, first %g, last %g", s(i), #e(), e(0), e(#e()-1));
EndFor
b() = BoundingBox Volume{v(0)};
Printf("box %.6g %.6g %.6g %.6g %.6g %.6g", b(0), b(1), b(2), b(3), b(4), b(5));
