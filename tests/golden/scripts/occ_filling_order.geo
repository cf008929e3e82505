// The order in which Boundary lists the curves of fillings, as the reference lists them. A
// filling faces the side about which its loop turns counter-clockwise (the loop runs the way
// its first curve goes, turned round when that curve is negative), but its curves are listed
// the way the parameters of its plate run round it: from the loop's first stored curve (its
// first, or its last when the first is negative) when the plate faces the same side, else the
// other way round, ending at that curve. Which side the plate faces is OpenCASCADE's choice.
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

// A unit square at x = x0, z = 0 or lifted at one corner: points 10*k + 0..3, lines 10*k +
// 0..3 counter-clockwise from its lower left corner.
Macro Square
  For i In {0:3}
    Point(10*k + i) = {x0 + (i == 1 || i == 2), (i >= 2), lift * (i == 1)};
  EndFor
  For i In {0:3}
    Line(10*k + i) = {10*k + i, 10*k + (i + 1) % 4};
  EndFor
Return

// Plane squares: counter-clockwise, clockwise, from a negative first curve, in a shuffled order.
lift = 0;
k = 1; x0 = 0; Call Square;
Curve Loop(10) = {10, 11, 12, 13};
Surface(1) = {10};
s = 1; Call PrintBoundary;
k = 2; x0 = 2; Call Square;
Curve Loop(20) = {-23, -22, -21, -20};
Surface(2) = {20};
s = 2; Call PrintBoundary;
k = 3; x0 = 4; Call Square;
Curve Loop(30) = {-31, 32, 33, 30};
Surface(3) = {30};
s = 3; Call PrintBoundary;
k = 4; x0 = 6; Call Square;
Curve Loop(40) = {42, -41, 40, -43};
Surface(4) = {40};
s = 4; Call PrintBoundary;

// The same loops, one corner lifted: the plate is no plane.
lift = 0.3;
k = 5; x0 = 8; Call Square;
Curve Loop(50) = {50, 51, 52, 53};
Surface(5) = {50};
s = 5; Call PrintBoundary;
k = 6; x0 = 10; Call Square;
Curve Loop(60) = {-63, -62, -61, -60};
Surface(6) = {60};
s = 6; Call PrintBoundary;
k = 7; x0 = 12; Call Square;
Curve Loop(70) = {-71, 72, 73, 70};
Surface(7) = {70};
s = 7; Call PrintBoundary;
k = 8; x0 = 14; Call Square;
Curve Loop(80) = {82, -81, 80, -83};
Surface(8) = {80};
s = 8; Call PrintBoundary;

// Through a point above the middle.
k = 9; x0 = 16; Call Square;
Curve Loop(90) = {93, 92, 91, 90};
Point(99) = {16.5, 0.5, 0.4};
Surface(9) = {90} Using Point{99};
s = 9; Call PrintBoundary;

// A disk of two half circles (which turn clockwise), in all four ways of giving its loop.
Point(100) = {0, 5, 0};
Point(101) = {2, 5, 0};
Point(102) = {-2, 5, 0};
Circle(100) = {101, 100, 102};
Circle(101) = {102, 100, 101};
Curve Loop(100) = {100, 101};
Surface(10) = {100};
s = 10; Call PrintBoundary;
Curve Loop(110) = {101, 100};
Surface(11) = {110};
s = 11; Call PrintBoundary;
Curve Loop(120) = {-100, -101};
Surface(12) = {120};
s = 12; Call PrintBoundary;
Curve Loop(130) = {-101, -100};
Surface(13) = {130};
s = 13; Call PrintBoundary;

// A triangle. Given counter-clockwise, its plate faces -z: it is listed clockwise, ending at
// its first curve. Given clockwise from a negative curve, its plate faces +z: it is listed
// counter-clockwise, ending at its last curve.
Point(140) = {20, 0, 0};
Point(141) = {30, 0, 0};
Point(142) = {20, 10, 0};
Line(140) = {140, 141};
Line(141) = {141, 142};
Line(142) = {142, 140};
Curve Loop(140) = {140, -142, -141};
Surface(14) = {140};
s = 14; Call PrintBoundary;
Curve Loop(150) = {-140, -142, -141};
Surface(15) = {150};
s = 15; Call PrintBoundary;
