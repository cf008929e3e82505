// B-splines whose first control point is repeated last: as in the reference, a periodic curve
// (uniform knots; degree 3, or the number of distinct points when smaller) that does not pass
// through its points. It gets a vertex of its own, under the next point tag, with the mesh
// size the repeated point has; the surface it bounds meshes as any other.
SetFactory("OpenCASCADE");
Point(1) = {1, 0, 0, 0.1};
Point(2) = {0, 1, 0, 0.5};
Point(3) = {-1, 0, 0, 0.5};
Point(4) = {0, -1, 0, 0.5};
BSpline(1) = {1, 2, 3, 4, 1};
Curve Loop(1) = {1};
Plane Surface(1) = {1};

Macro PrintEnds
  e() = Boundary{ Curve{c}; };
  xyz() = Point{e(0)};
  p() = Point{:};
  Printf("curve %g: closed at point %g (%.6f, %.6f, %.6f); %g points", c, e(0), xyz(0), xyz(1),
         xyz(2), #p());
Return

c = 1; Call PrintEnds;
// Three distinct points: still of degree 3.
Point(6) = {3, 0, 0};
Point(7) = {4, 1, 0};
Point(8) = {5, -0.5, 0};
BSpline(2) = {6, 7, 8, 6};
c = 2; Call PrintEnds;
// Two: of degree 2.
Point(10) = {3, 3, 0};
Point(11) = {4, 4, 1};
BSpline(3) = {10, 11, 10};
c = 3; Call PrintEnds;
