// geomesh tutorial 1: a rectangular plate with an octagonal hole.
//
// The plate is built point by point from the built-in kernel: points carry the target
// element size, lines join points, a curve loop closes a boundary, and a plane surface is
// bounded by an outer loop and any number of hole loops. Physical groups name what a solver
// needs: the material region and the boundaries where conditions apply.
//
// Run:  geomesh t1.geo -2          (writes t1.msh)

width = 2.0;      // plate size
height = 1.0;
radius = 0.25;    // hole "radius" (distance from centre to the octagon's corners)
size = 0.08;      // element size on the plate's edges
holeSize = size / 2;  // finer elements around the hole

// The plate's corners, counter-clockwise.
Point(1) = {0, 0, 0, size};
Point(2) = {width, 0, 0, size};
Point(3) = {width, height, 0, size};
Point(4) = {0, height, 0, size};

Line(1) = {1, 2};  // bottom
Line(2) = {2, 3};  // right
Line(3) = {3, 4};  // top
Line(4) = {4, 1};  // left

// The hole: eight corners on a circle around the plate's centre.
cx = width / 2;
cy = height / 2;
c = radius * Sqrt(2) / 2;
Point(11) = {cx + radius, cy, 0, holeSize};
Point(12) = {cx + c, cy + c, 0, holeSize};
Point(13) = {cx, cy + radius, 0, holeSize};
Point(14) = {cx - c, cy + c, 0, holeSize};
Point(15) = {cx - radius, cy, 0, holeSize};
Point(16) = {cx - c, cy - c, 0, holeSize};
Point(17) = {cx, cy - radius, 0, holeSize};
Point(18) = {cx + c, cy - c, 0, holeSize};

Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};
Line(15) = {15, 16};
Line(16) = {16, 17};
Line(17) = {17, 18};
Line(18) = {18, 11};

Curve Loop(1) = {1, 2, 3, 4};                        // outer boundary
Curve Loop(2) = {11, 12, 13, 14, 15, 16, 17, 18};    // the hole
Plane Surface(1) = {1, 2};

// Named groups: the solver sees these, and only these, in the mesh file.
Physical Surface("plate", 1) = {1};
Physical Curve("clamped", 2) = {4};
Physical Curve("loaded", 3) = {2};
Physical Curve("free", 4) = {1, 3};
Physical Curve("hole", 5) = {11, 12, 13, 14, 15, 16, 17, 18};

Printf("plate %g x %g with a hole of radius %g; element size %g", width, height, radius, size);
