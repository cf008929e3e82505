// Older and rarer forms of the language, each giving what the reference gives.
x() = {1 ... 3};  // the old spelling of {1:3}
y() = {3 ... 1};
Printf("range %g %g %g, down %g %g", x(0), x(2), #x(), y(0), #y());
Point(0) = {0, 0, 0};
Point(-1) = {1, 0, 0};  // a negative tag is the next free one: 1
Point(2) = {1, 1, 0};
Point(-7) = {0, 1, 0};  // 3
p() = Point{:};
Printf("points %g %g %g %g", p(0), p(1), p(2), p(3));
Line(0) = {0, -1};  // signs of points do not matter
Line(-2) = {1, 2};  // curve 1
Line(3) = {2, 3, 0};  // one curve through three points
c() = Curve "*";
For i In {0:#c() - 1}
  b() = Boundary{Curve{c(i)};};
  Printf("curve %g: %g -> %g", c(i), b(0), b(1));
EndFor
Curve Loop(0) = {0, 1, 3};
Plane Surface(-4) = {0};
Printf("surface %g, newp %g newl %g news %g newll %g", Surface{:}, newp, newl, news, newll);
Physical Curve(-3) = {1, 3};  // a physical group's negative tag is its opposite
Physical Point(-9) = {1};
Physical Point(2) = {2};
g() = Physical Point "*";
Printf("physicals %g %g %g", Physical Curve{:}, g(0), g(1));
// Ellipsis, CatmullRom, Using Power: older names of Ellipse, Spline, Using Progression
Point(10) = {3, 0, 0}; Point(11) = {2, 0, 0}; Point(12) = {4, 0, 0}; Point(13) = {3, 0.5, 0};
Ellipsis(10) = {11, 10, 12, 13};
CatmullRom(11) = {11, 13, 12};
Transfinite Line{11} = 5 Using Power 1.5;
b() = Boundary{Curve{10};};
Printf("ellipse %g -> %g", b(0), b(1));
// The plane of a half circle says which way it turns.
Point(20) = {0, 0, 5}; Point(21) = {1, 0, 5}; Point(22) = {-1, 0, 5};
Circle(20) = {21, 20, 22} Plane{0, 0, 1};
Circle(21) = {21, 20, 22} Plane{0, 0, -1};
Circle(22) = {21, 20, 22} Plane{0, 1, 0};
up() = BoundingBox Curve{20};
down() = BoundingBox Curve{21};
side() = BoundingBox Curve{22};
Printf("half circles %g %g %g", up(4) > 0.9, down(1) < -0.9, side(2) < 4.5);
// Split Curve: the pieces between the given points get new tags.
Point(30) = {0, 0, 9}; Point(31) = {1, 0.5, 9}; Point(32) = {2, -0.5, 9};
Point(33) = {3, 0.3, 9}; Point(34) = {4, 0, 9};
Spline(30) = {30, 31, 32, 33, 34};
Split Curve{30} Point{31, 33};
For t In {newl - 3:newl - 1}
  b() = Boundary{Curve{t};};
  Printf("piece %g: %g -> %g", t, b(0), b(1));
EndFor
PolarSphere(40) = {0, 1};  // defines no entity
s() = Surface{:};
Printf("%g surfaces", #s());
Printf(StrCat("file ", CurrentFileName, ", date of ", Sprintf("%g", StrLen(Today)), " characters"));
Printf(LowerCaseIn("ABC"));
