// Huge sizes everywhere: each curve gets the fewest segments its kind allows. Straight lines
// keep one; circle and ellipse arcs get their share of Mesh.MinimumCircleNodes per full turn;
// splines get Mesh.MinimumCurveNodes - 1, even through aligned points.
Mesh.MinimumCircleNodes = 30;
Mesh.MinimumCurvePoints = 6;  // the old name
Point(1) = {0, 0, 0, 100};
Point(2) = {1, 1, 0, 100};
Point(3) = {2, 0, 0, 100};
Point(5) = {5, 0, 0, 100};
Point(6) = {6, 0, 0, 100};
Point(7) = {7, 0, 0, 100};
Point(8) = {5, 1, 0, 100};
Ellipse(2) = {6, 5, 7, 8};  // a quarter: 30 / 4, rounded up
BSpline(3) = {1, 8, 6};
Line(4) = {5, 8};
Point(9) = {0, 3, 0, 100};
Point(10) = {1, 3, 0, 100};
Point(11) = {2, 3, 0, 100};
Spline(5) = {9, 10, 11};
Point(12) = {10, 0, 0, 100};
Point(13) = {11, 0, 0, 100};
Point(14) = {10, 1, 0, 100};
Point(15) = {9, 0, 0, 100};
Circle(6) = {13, 12, 14};
Circle(7) = {14, 12, 15};
