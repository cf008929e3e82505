// Entity queries on a built-in model: coordinates, bounding boxes, boundaries, PointsOf,
// entities in a box, and the counters for new tags.
lc = 0.2;
Point(1) = {0, 0, 0, lc}; Point(2) = {2, 0, 0, lc}; Point(3) = {2, 1, 0, lc};
Point(4) = {0, 1, 0, lc}; Point(5) = {1, 0.5, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point{5} In Surface{1};
xyz[] = Point{3};
Printf("point 3 at %g %g %g", xyz[0], xyz[1], xyz[2]);
bb[] = BoundingBox Surface{1};
Printf("surface box %g %g %g %g %g %g", bb[]);
bl[] = BoundingBox Curve{2};
Printf("curve box %g %g %g %g %g %g", bl[]);
b[] = Boundary{ Surface{1}; };
Printf("boundary of the surface: %g curves: %g %g %g %g", #b[], b[]);
e[] = Boundary{ Curve{1}; };
Printf("ends of curve 1: %g %g", e[]);
pts[] = PointsOf{ Surface{1}; };
Printf("points of the surface: %g", #pts[]);
inbox[] = Point In BoundingBox{-0.1, -0.1, -0.1, 1.1, 1.1, 0.1};
Printf("points in the left box: %g", #inbox[]);
cin[] = Curve In BoundingBox{-0.1, -0.1, -0.1, 2.1, 0.1, 0.1};
Printf("curves along y = 0: %g (curve %g)", #cin[], cin[0]);
Printf("next tags: point %g, curve %g, surface %g, volume %g, region %g",
       newp, newl, news, newv, newreg);
Point(newp) = {3, 0, 0, lc};
Line(newl) = {2, 6};
Printf("after adding: point %g, curve %g, loop %g", newp, newl, newll);
all[] = Point{:};
Printf("all points: %g", #all[]);
Printf("model box x %g..%g, y %g..%g, diagonal %.6g", General.MinX, General.MaxX, General.MinY,
       General.MaxY, General.BoundingBoxSize);
