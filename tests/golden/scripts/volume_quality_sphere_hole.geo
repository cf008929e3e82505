// A box with a spherical cavity, finer on the sphere: the graded sizes leave slivers next to
// the sphere, which the mesher replaces or the optimizer removes. The sphere is eight octants, each a three-sided filling
// surface bounded by quarter circles.
lc = 0.25;
lcs = 0.08;
r = 0.3;
Point(1) = {0, 0, 0, lc};  Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc};  Point(4) = {0, 1, 0, lc};
Point(5) = {0, 0, 1, lc};  Point(6) = {1, 0, 1, lc};
Point(7) = {1, 1, 1, lc};  Point(8) = {0, 1, 1, lc};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
Line(5) = {5, 6};  Line(6) = {6, 7};  Line(7) = {7, 8};  Line(8) = {8, 5};
Line(9) = {1, 5};  Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
Curve Loop(1) = {-4, -3, -2, -1};  Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8};      Plane Surface(2) = {2};
Curve Loop(3) = {1, 10, -5, -9};   Plane Surface(3) = {3};
Curve Loop(4) = {2, 11, -6, -10};  Plane Surface(4) = {4};
Curve Loop(5) = {3, 12, -7, -11};  Plane Surface(5) = {5};
Curve Loop(6) = {4, 9, -8, -12};   Plane Surface(6) = {6};
Surface Loop(1) = {1:6};

c = 100;
Point(c) = {0.5, 0.5, 0.5, lcs};
Point(c + 1) = {0.5 + r, 0.5, 0.5, lcs};  Point(c + 2) = {0.5, 0.5 + r, 0.5, lcs};
Point(c + 3) = {0.5 - r, 0.5, 0.5, lcs};  Point(c + 4) = {0.5, 0.5 - r, 0.5, lcs};
Point(c + 5) = {0.5, 0.5, 0.5 + r, lcs};  Point(c + 6) = {0.5, 0.5, 0.5 - r, lcs};
// Equator, then the meridians to the north (5) and south (6) poles.
Circle(101) = {c + 1, c, c + 2};  Circle(102) = {c + 2, c, c + 3};
Circle(103) = {c + 3, c, c + 4};  Circle(104) = {c + 4, c, c + 1};
Circle(105) = {c + 1, c, c + 5}; Circle(106) = {c + 2, c, c + 5};
Circle(107) = {c + 3, c, c + 5}; Circle(108) = {c + 4, c, c + 5};
Circle(109) = {c + 1, c, c + 6}; Circle(110) = {c + 2, c, c + 6};
Circle(111) = {c + 3, c, c + 6}; Circle(112) = {c + 4, c, c + 6};
Curve Loop(101) = {101, 106, -105};  Surface(101) = {101};
Curve Loop(102) = {102, 107, -106};  Surface(102) = {102};
Curve Loop(103) = {103, 108, -107};  Surface(103) = {103};
Curve Loop(104) = {104, 105, -108};  Surface(104) = {104};
Curve Loop(105) = {-101, 109, -110}; Surface(105) = {105};
Curve Loop(106) = {-102, 110, -111}; Surface(106) = {106};
Curve Loop(107) = {-103, 111, -112}; Surface(107) = {107};
Curve Loop(108) = {-104, 112, -109}; Surface(108) = {108};
Surface Loop(2) = {101:108};
Volume(1) = {1, 2};
