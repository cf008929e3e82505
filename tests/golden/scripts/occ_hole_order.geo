// The order in which Boundary lists the curves of plane surfaces with holes, as the reference
// lists them: the outer loop as the script's loop runs (the way its first curve goes), from its
// first curve; each hole as its loop reversed as a whole, from its last curve. A hole whose
// first curve runs clockwise is thus listed counter-clockwise. Faces made by Booleans list
// their loops the way they bound the face.
SetFactory("OpenCASCADE");

// Prints "surface s: " and the curves of its boundary; an empty line first, which the
// reference's progress line of a Boolean may swallow in place of the listing.
Macro PrintBoundary
  Printf("");
  c() = Boundary{ Surface{s}; };
  line = Sprintf("surface %g:", s);
  For i In {0:#c()-1}
    line = StrCat(line, Sprintf(" %g", c(i)));
  EndFor
  Printf(line);
Return

// A 4 x 4 square at x = x0 (lines 10*k + 0..3, counter-clockwise), curve loop 10*k; a unit
// square hole inside it (lines 10*k + 4..7, counter-clockwise from its lower left corner).
Macro SquareWithHole
  For i In {0:3}
    Point(10*k + i) = {x0 + 4*(i == 1 || i == 2), 4*(i >= 2), 0, 0.25};
    Point(10*k + 4 + i) = {x0 + 1 + (i == 1 || i == 2), 1 + (i >= 2), 0, 0.25};
  EndFor
  For i In {0:3}
    Line(10*k + i) = {10*k + i, 10*k + (i + 1) % 4};
    Line(10*k + 4 + i) = {10*k + 4 + i, 10*k + 4 + (i + 1) % 4};
  EndFor
Return

// The hole counter-clockwise, from its second curve.
k = 1; x0 = 0; Call SquareWithHole;
Curve Loop(10) = {10, 11, 12, 13};
Curve Loop(11) = {15, 16, 17, 14};
Plane Surface(1) = {10, 11};
s = 1; Call PrintBoundary;

// The hole listed clockwise, each curve still counter-clockwise: the loop runs the way its
// first curve goes.
k = 2; x0 = 10; Call SquareWithHole;
Curve Loop(20) = {20, 21, 22, 23};
Curve Loop(21) = {27, 26, 25, 24};
Plane Surface(2) = {20, 21};
s = 2; Call PrintBoundary;

// The outer loop listed clockwise, each curve counter-clockwise.
k = 3; x0 = 20; Call SquareWithHole;
Curve Loop(30) = {33, 32, 31, 30};
Curve Loop(31) = {34, 35, 36, 37};
Plane Surface(3) = {30, 31};
s = 3; Call PrintBoundary;

// A triangular hole whose curves run clockwise, and a hole of two half circles (clockwise,
// as half circles turn), and a whole circle: listed counter-clockwise, in the order given.
For i In {0:3}
  Point(40 + i) = {30 + 6*(i == 1 || i == 2), 6*(i >= 2), 0, 0.25};
EndFor
For i In {0:3}
  Line(40 + i) = {40 + i, 40 + (i + 1) % 4};
EndFor
Point(44) = {31, 1, 0, 0.25};
Point(45) = {32, 1, 0, 0.25};
Point(46) = {32, 2, 0, 0.25};
Line(44) = {44, 46};
Line(45) = {46, 45};
Line(46) = {45, 44};
Point(47) = {34, 2, 0, 0.25};
Point(48) = {34.5, 2, 0, 0.25};
Point(49) = {33.5, 2, 0, 0.25};
Circle(47) = {48, 47, 49};
Circle(48) = {49, 47, 48};
Circle(49) = {33, 4.5, 0, 0.5};
Curve Loop(40) = {40, 41, 42, 43};
Curve Loop(41) = {45, 44, 46};
Curve Loop(42) = {47, 48};
Curve Loop(43) = {49};
Plane Surface(4) = {40, 41, 42, 43};
s = 4; Call PrintBoundary;

// A face made by a Boolean difference: its hole is listed clockwise, the way it bounds the
// face.
Rectangle(5) = {40, 0, 0, 4, 4};
Rectangle(6) = {41, 1, 0, 1, 1};
BooleanDifference(7) = { Surface{5}; Delete; }{ Surface{6}; Delete; };
MeshSize{ PointsOf{ Surface{7}; } } = 0.25;
s = 7; Call PrintBoundary;
