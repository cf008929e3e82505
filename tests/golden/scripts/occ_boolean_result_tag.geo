// Booleans that give their result a tag: the reference numbers the result anew. Every deleted
// input goes, even one the operation kept as it was; the result's sub-shapes that an entity
// still there holds keep their tags, the others take the next free ones in the result's order,
// so the faces of a box that a deleted sphere hollows out are 1..6 again.
SetFactory("OpenCASCADE");

Macro PrintTags
  line = "";
  For i In {0:#l() - 1}
    line = StrCat(line, Sprintf(" %g", l(i)));
  EndFor
  Printf(StrCat(what, ":", line));
Return

// A box with a spherical cavity, both deleted.
Box(1) = {0, 0, 0, 2, 2, 2};
Sphere(2) = {1, 1, 1, 0.5};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
what = "cavity faces"; l() = Boundary{ Volume{3}; }; Call PrintTags;
what = "cavity curves"; l() = Curve{:}; Call PrintTags;
what = "cavity points"; l() = Point{:}; Call PrintTags;

// An elliptic plate with a hole (2D): the ellipse is numbered before the hole.
Disk(11) = {10, 0, 0, 3, 1.5};
Disk(12) = {10.8, 0, 0, 0.4};
BooleanDifference(13) = { Surface{11}; Delete; }{ Surface{12}; Delete; };
what = "plate curves"; l() = Boundary{ Surface{13}; }; Call PrintTags;

// A corner cut away by a box that stays: the box keeps its tag, the cut faces are new.
Box(21) = {20, 0, 0, 1, 1, 1};
Box(22) = {20.5, 0.5, 0.5, 1, 1, 1};
BooleanDifference(23) = { Volume{21}; Delete; }{ Volume{22}; };
what = "corner faces"; l() = Boundary{ Volume{23}; }; Call PrintTags;
what = "volumes"; l() = Volume{:}; Call PrintTags;

// Three boxes joined into one.
Box(31) = {30, 0, 0, 1, 1, 1};
Box(32) = {31, 0, 0, 1, 1, 1};
Box(33) = {30.5, 0.25, 0.25, 1, 0.5, 0.5};
BooleanUnion(34) = { Volume{31, 32}; Delete; }{ Volume{33}; Delete; };
what = "union faces"; l() = Boundary{ Volume{34}; }; Call PrintTags;

// A point fragmenting a face: the point, deleted, is numbered anew with the face.
Rectangle(41) = {40, 0, 0, 2, 1};
Point(60) = {40.5, 0.5, 0};
BooleanFragments(42) = { Surface{41}; Delete; }{ Point{60}; Delete; };
what = "fragment points"; l() = Point{:}; l() = l({#l() - 5:#l() - 1}); Call PrintTags;
b() = BoundingBox Point{l(4)};
Printf("the point, numbered last, at x = %g", b(0));

// An intersection keeping both inputs.
Box(50) = {50, 0, 0, 1, 1, 1};
Sphere(51) = {50.5, 0.5, 1, 0.4};
BooleanIntersection(52) = { Volume{50}; }{ Volume{51}; };
what = "intersection faces"; l() = Boundary{ Volume{52}; }; Call PrintTags;

// Fragments of a box and a square apart from it: only the volume takes the tag, the square,
// deleted, is gone.
Box(61) = {60, 0, 0, 1, 1, 1};
Rectangle(62) = {63, 0, 0, 1, 1};
BooleanFragments(63) = { Volume{61}; Delete; }{ Surface{62}; Delete; };
what = "volumes"; l() = Volume{:}; Call PrintTags;
l() = Surface{:};
Printf("%g surfaces, the last %g", #l(), l(#l() - 1));
