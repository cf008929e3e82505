// Transformations, copies and deletions of OpenCASCADE shapes: each transformed shape keeps
// its tag while its points, curves and surfaces are numbered anew, as the reference does.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Sphere(2) = {3, 0, 0, 0.5};
d() = Duplicata{ Volume{1}; };
Printf("copy: volume %g", d(0));
Translate {0, 2, 0} { Volume{d(0)}; }
Dilate {{0, 0, 0}, 2} { Volume{2}; }
Rotate {{0, 0, 1}, {0, 0, 0}, Pi/2} { Volume{1}; }
Symmetry {1, 0, 0, -10} { Volume{d(0)}; }
p() = PointsOf{ Volume{d(0)}; };
Printf("the copy's points: %g to %g", p(0), p(#p() - 1));
s() = Boundary{ Volume{2}; };
Printf("the ball's surface: %g", s(0));
b() = BoundingBox Volume{d(0)};
Printf("the copy's box: %.6g %.6g %.6g %.6g %.6g %.6g", b(0), b(1), b(2), b(3), b(4), b(5));
Delete { Volume{2}; }
Recursive Delete { Volume{1}; }
v() = Volume{:}; s() = Surface{:}; c() = Curve{:}; p() = Point{:};
Printf("left: %g volume(s), %g surfaces, %g curves, %g points", #v(), #s(), #c(), #p());
Printf("next: point %g, curve %g, surface %g, volume %g", newp, newl, news, newv);
