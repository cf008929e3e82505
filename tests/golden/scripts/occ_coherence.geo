// Coherence on the OpenCASCADE model: touching volumes are glued (fragmented together); the
// plane surfaces beside them, of a lower dimension, stay as they are.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
Box(3) = {0, 1, 0, 2, 1, 1};
Rectangle(30) = {0, 0, 3, 1, 1};
Rectangle(31) = {0.5, 0, 3, 1, 1};
Coherence;
v() = Volume{:}; s() = Surface{:}; c() = Curve{:}; p() = Point{:};
Printf("%g volumes, %g surfaces (first %g, last %g), %g curves, %g points", #v(), #s(), s(0),
       s(#s() - 1), #c(), #p());
For i In {0:#v()-1}
  f() = Boundary{ Volume{v(i)}; };
  Printf("volume %g: %g faces, first %g", v(i), #f(), f(0));
EndFor
