// BooleanFragments of points with a surface and with a volume: the points inside keep their
// tags and are embedded; the model the reference makes of it and the list it returns.
SetFactory("OpenCASCADE");

Macro PrintList  // r() as one line
  text = "returned:";
  For i In {0:#r()-1}
    text = StrCat(text, Sprintf(" %g", r(i)));
  EndFor
  Printf(text);
Return

Rectangle(1) = {0, 0, 0, 1, 1};
Point(10) = {0.5, 0.5, 0};
Point(11) = {0.2, 0.7, 0};
Point(12) = {3, 3, 3};
r() = BooleanFragments{ Surface{1}; Delete; }{ Point{10, 11, 12}; Delete; };
Call PrintList;  // the surface, its new curves, the points, those inside it again
p() = Point{:}; c() = Curve{:}; s() = Surface{:};
Printf("surface: %g points (first %g, last %g), %g curves, surfaces %g", #p(), p(0), p(#p()-1),
       #c(), s(0));
e() = Boundary{ Surface{1}; };
Printf("its boundary: %g %g %g %g", e(0), e(1), e(2), e(3));

Box(5) = {5, 0, 0, 1, 1, 1};
Point(30) = {5.5, 0.5, 0.5};
Point(31) = {5.25, 0.5, 1};
r() = BooleanFragments{ Volume{5}; Delete; }{ Point{30, 31}; Delete; };
Call PrintList;

Rectangle(60) = {0, 5, 0, 1, 1};
Point(70) = {0.5, 5.5, 0};
Point(71) = {0.5, 5, 0};
r() = BooleanFragments{ Surface{60}; }{ Point{70, 71}; };  // nothing deleted; a point on a side
Call PrintList;
p() = Point{:}; c() = Curve{:}; s() = Surface{:}; v() = Volume{:};
Printf("volume: %g points (last %g), %g curves, %g surfaces (last %g), volume %g", #p(),
       p(#p()-1), #c(), #s(), s(#s()-1), v(0));
f() = Boundary{ Volume{5}; };
Printf("its faces: %g %g %g %g %g %g", f(0), f(1), f(2), f(3), f(4), f(5));
Mesh.MeshSizeMax = 0.25;
