// A wire and two probe points embedded in a column built by extrusion (built-in kernel): the
// wire's segments are edges of the tetrahedra and the points are their nodes. As in the
// reference, their fine sizes stay on them and do not refine the volume around.
lc = 0.15;
Point(1) = {0, 0, 0, lc};
Extrude {1, 0, 0} { Point{1}; }
Extrude {0, 1, 0} { Curve{1}; }
Extrude {0, 0, 2} { Surface{5}; }
Point(100) = {0.5, 0.5, 0.4, 0.02};
Point(101) = {0.6, 0.4, 1.6, 0.02};
Line(100) = {100, 101};
Point(102) = {0.2, 0.75, 1.0, 0.03};
Point(103) = {0.8, 0.25, 1.0, 0.03};
Curve{100} In Volume{1};
Point{102, 103} In Volume{1};
