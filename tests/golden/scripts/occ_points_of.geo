// PointsOf on OpenCASCADE entities: a curve's start and end, as Boundary gives them; a surface's
// and a volume's points in ascending tags.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Sphere(2) = {3, 0, 0, 1};
For c In {1:4}
  b() = Boundary{ Curve{c}; };
  q() = PointsOf{ Curve{c}; };
  Printf("curve %g: boundary %g %g, points %g %g", c, b(0), b(1), q(0), q(1));
EndFor
q() = PointsOf{ Curve{-1}; };
Printf("curve -1: points %g %g", q(0), q(1));
For s In {1:7}
  q() = PointsOf{ Surface{s}; };
  Printf("surface %g: %g points: %g %g ... %g %g", s, #q(), q(0), q(1), q(#q()-2), q(#q()-1));
EndFor
q() = PointsOf{ Volume{1}; };
Printf("volume: %g %g %g %g %g %g %g %g", q(0), q(1), q(2), q(3), q(4), q(5), q(6), q(7));
