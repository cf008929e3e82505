// geomesh tutorial 5: a solid with a cavity, meshed with tetrahedra.
//
// A sealed housing with a pitched roof and a rectangular chamber inside it, built face by
// face with the built-in kernel: points, lines, curve loops and plane surfaces as in
// tutorial 1, then surface loops that close a region of space and a volume bounded by an
// outer surface loop and one loop per cavity. Option -3 meshes the volume with
// tetrahedra; sizes on points grade them, finer around the chamber; Mesh.Optimize improves
// the worst of them.
//
// Run:  geomesh t5.geo -3          (writes t5.msh)

L = 3.0;          // length along x
W = 2.0;          // width along y
H = 1.5;          // height of the walls
R = 2.2;          // height of the ridge
lc = 0.25;        // element size on the outside
lcIn = 0.1;       // element size on the chamber

// The outside: a box with a pitched roof, its ridge along x at y = W/2.
Point(1) = {0, 0, 0, lc};    Point(2) = {L, 0, 0, lc};
Point(3) = {L, W, 0, lc};    Point(4) = {0, W, 0, lc};
Point(5) = {0, 0, H, lc};    Point(6) = {L, 0, H, lc};
Point(7) = {L, W, H, lc};    Point(8) = {0, W, H, lc};
Point(9) = {0, W / 2, R, lc};
Point(10) = {L, W / 2, R, lc};

Line(1) = {1, 2};   Line(2) = {2, 3};   Line(3) = {3, 4};   Line(4) = {4, 1};    // floor
Line(5) = {1, 5};   Line(6) = {2, 6};   Line(7) = {3, 7};   Line(8) = {4, 8};    // corners
Line(9) = {5, 6};   Line(10) = {7, 8};                                          // eaves
Line(11) = {5, 9};  Line(12) = {9, 8};  Line(13) = {6, 10}; Line(14) = {10, 7}; // gables
Line(15) = {9, 10};                                                             // ridge

// Each face is a closed loop of curves; a minus sign runs a curve backwards so that the
// loop is a single chain. The loops below turn so that every face's normal points out of
// the housing (counter-clockwise when seen from outside): a good habit, which keeps the
// orientation of boundary elements predictable for solvers.
Curve Loop(1) = {-4, -3, -2, -1};      Plane Surface(1) = {1};   // floor
Curve Loop(2) = {1, 6, -9, -5};        Plane Surface(2) = {2};   // front wall (y = 0)
Curve Loop(3) = {3, 8, -10, -7};       Plane Surface(3) = {3};   // back wall (y = W)
Curve Loop(4) = {5, 11, 12, -8, 4};    Plane Surface(4) = {4};   // gable at x = 0
Curve Loop(5) = {2, 7, -14, -13, -6};  Plane Surface(5) = {5};   // gable at x = L
Curve Loop(6) = {9, 13, -15, -11};     Plane Surface(6) = {6};   // roof, front
Curve Loop(7) = {10, -12, 15, 14};     Plane Surface(7) = {7};   // roof, back

// A surface loop lists the faces that enclose a region: here, the whole outside.
Surface Loop(1) = {1:7};

// The chamber: a box from (x1, y1, z1) to (x2, y2, z2), with the finer size.
x1 = 1.0;  x2 = 2.0;
y1 = 0.5;  y2 = 1.5;
z1 = 0.3;  z2 = 1.2;
Point(11) = {x1, y1, z1, lcIn};  Point(12) = {x2, y1, z1, lcIn};
Point(13) = {x2, y2, z1, lcIn};  Point(14) = {x1, y2, z1, lcIn};
Point(15) = {x1, y1, z2, lcIn};  Point(16) = {x2, y1, z2, lcIn};
Point(17) = {x2, y2, z2, lcIn};  Point(18) = {x1, y2, z2, lcIn};
Line(21) = {11, 12};  Line(22) = {12, 13};  Line(23) = {13, 14};  Line(24) = {14, 11};
Line(25) = {15, 16};  Line(26) = {16, 17};  Line(27) = {17, 18};  Line(28) = {18, 15};
Line(29) = {11, 15};  Line(30) = {12, 16};  Line(31) = {13, 17};  Line(32) = {14, 18};
// Out of the housing, here, is into the chamber: these loops turn the other way.
Curve Loop(21) = {21, 22, 23, 24};      Plane Surface(21) = {21};
Curve Loop(22) = {-28, -27, -26, -25};  Plane Surface(22) = {22};
Curve Loop(23) = {29, 25, -30, -21};    Plane Surface(23) = {23};
Curve Loop(24) = {30, 26, -31, -22};    Plane Surface(24) = {24};
Curve Loop(25) = {31, 27, -32, -23};    Plane Surface(25) = {25};
Curve Loop(26) = {32, 28, -29, -24};    Plane Surface(26) = {26};
Surface Loop(2) = {21:26};

// The solid: what is inside loop 1 and outside loop 2. Further loops would be further
// cavities. (Volume(2) = {2} would fill the chamber itself, as a second material.)
Volume(1) = {1, 2};

// Tetrahedra straight out of the Delaunay mesher include flat ones ("slivers"), whose
// quality is near 0 and which spoil a solver's accuracy. Mesh.Optimize (on by default;
// written here to show it) smooths the inner nodes, then swaps faces, removes edges and moves
// nodes wherever a tetrahedron is below Mesh.OptimizeThreshold, measured by gamma (1 for a
// regular tetrahedron); geomesh also works on those below 0.45 when the threshold is lower.
// Try Mesh.Optimize = 0 and compare the quality in the summary geomesh prints at the end.
Mesh.Optimize = 1;
Mesh.OptimizeThreshold = 0.3;

Physical Volume("housing", 1) = {1};
Physical Surface("floor", 2) = {1};
Physical Surface("chamber", 3) = {21:26};
