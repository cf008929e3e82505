// A curve loop whose first curve is negative runs against the way that curve goes (the signs
// of the other curves do not matter), and a plane surface bounded by it faces the other way:
// the squares below face -z (their meshes too), the last one +z. Their curves are listed as
// those of the loop reversed as a whole: the outer loop the way it runs, from its last curve;
// a hole against the way it runs, from its first curve.
SetFactory("OpenCASCADE");

Macro PrintBoundary
  Printf("");
  c() = Boundary{ Surface{s}; };
  line = Sprintf("surface %g:", s);
  For i In {0:#c()-1}
    line = StrCat(line, Sprintf(" %g", c(i)));
  EndFor
  Printf(line);
Return

// A 4 x 4 square at x = x0 (lines 10*k + 0..3, counter-clockwise); a unit square hole inside it
// (lines 10*k + 4..7, counter-clockwise from its lower left corner).
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

// The outer loop clockwise, all its curves negative; the hole counter-clockwise.
k = 1; x0 = 0; Call SquareWithHole;
Curve Loop(10) = {-13, -12, -11, -10};
Curve Loop(11) = {14, 15, 16, 17};
Plane Surface(1) = {10, 11};
s = 1; Call PrintBoundary;

// Only the first curve negative: the loop still runs clockwise.
k = 2; x0 = 10; Call SquareWithHole;
Curve Loop(20) = {-21, 22, 23, 20};
Curve Loop(21) = {-27, 26, 25, 24};
Plane Surface(2) = {20, 21};
s = 2; Call PrintBoundary;

// Curves given in the order opposite to the way they go, the first one negative, the others of
// either sign: clockwise too; the hole counter-clockwise.
k = 3; x0 = 20; Call SquareWithHole;
Curve Loop(30) = {-33, -32, 31, 30};
Curve Loop(31) = {-37, 36, -35, -34};
Plane Surface(3) = {30, 31};
s = 3; Call PrintBoundary;

// A hole of two half circles (which turn clockwise) from a negative first curve.
k = 4; x0 = 30; Call SquareWithHole;
Point(48) = {32, 2.5, 0, 0.25};
Point(49) = {32.5, 2.5, 0, 0.25};
Point(50) = {31.5, 2.5, 0, 0.25};
Circle(48) = {49, 48, 50};
Circle(49) = {50, 48, 49};
Curve Loop(40) = {40, 41, 42, 43};
Curve Loop(41) = {-48, 49};
Plane Surface(4) = {40, 41};
s = 4; Call PrintBoundary;
