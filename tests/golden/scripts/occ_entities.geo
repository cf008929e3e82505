// Points, lines, arcs, splines and plane surfaces with holes in the OpenCASCADE factory, and
// what Boundary, PointsOf and BoundingBox say of them.
SetFactory("OpenCASCADE");

Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 2, 0};
Point(4) = {0, 2, 0};
For i In {1:4}
  Line(i) = {i, i % 4 + 1};
EndFor
Point(5) = {1, 1, 0};
Point(6) = {1.5, 1, 0};
Point(7) = {0.5, 1, 0};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6};
Plane Surface(1) = {1, 2};
c() = Boundary{ Surface{1}; };
Printf("surface 1: %g curves", #c());
For i In {0:#c()-1}
  Printf("curve %g", c[i]);
EndFor
p() = PointsOf{ Surface{1}; };
Printf("its points: %g", #p());

Point(10) = {5, 0, 0};
Point(11) = {6, 0, 0};
Point(12) = {5, 1, 0};
Point(13) = {7, 1, 0};
Ellipse(20) = {11, 10, 11, 12};
Spline(21) = {10, 11, 13, 12};
BSpline(22) = {10, 11, 13, 12};
Bezier(23) = {10, 11, 13, 12};
For i In {20:23}
  e() = Boundary{ Curve{i}; };
  Printf("curve %g runs from %g to %g", i, e[0], e[1]);
EndFor
Printf("next: curve loop %g, surface %g", newll, news);
