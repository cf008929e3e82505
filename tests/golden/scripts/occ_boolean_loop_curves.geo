// Curves of surfaces deleted by a Boolean keep their tags while the script's curve loops
// hold them: the holes the tools cut are bounded by the tools' own curves 1 to 8, the disk by
// its half circles 9 and 10 (which turn clockwise about z, as the reference turns them).
SetFactory("OpenCASCADE");
Point(1) = {-5,1,0}; Point(2) = {5,1,0}; Point(3) = {5,3,0}; Point(4) = {-5,3,0};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};
Point(5) = {-5,-1,0}; Point(6) = {5,-1,0}; Point(7) = {5,-5,0}; Point(8) = {-5,-5,0};
Line(5) = {5,6}; Line(6) = {6,7}; Line(7) = {7,8}; Line(8) = {8,5};
Curve Loop(2) = {5,6,7,8}; Plane Surface(2) = {2};
Point(10) = {0,0,0}; Point(11) = {20,0,0}; Point(12) = {-20,0,0};
Circle(9) = {11,10,12}; Circle(10) = {12,10,11};
Curve Loop(3) = {9,10}; Plane Surface(3) = {3};
BooleanDifference{ Surface{3}; Delete; }{ Surface{1}; Surface{2}; Delete; }
b() = Boundary{Surface{3};};
For i In {0:#b()-1}
 bb() = BoundingBox Curve{Abs(b(i))};
 Printf("curve %g: %g %g %g %g", b(i), bb(0), bb(1), bb(3), bb(4));
EndFor
