// geomesh tutorial 3: structured and recombined meshes.
//
// A cooling channel seen from above: an inlet leg, a corner and an outlet leg, all one
// channel width wide, open into a plenum with a round pin in it. The channel is meshed as
// a grid of quadrangles: we say how many nodes each curve carries and how they are spaced
// (transfinite curves), fill each four-sided surface with the grid they define (transfinite
// surfaces), and merge its triangles into quadrangles (recombination). The plenum has no
// four sides; the Frontal-Delaunay for quads algorithm fills it with right-angled
// triangles that recombine into quadrangles too.
//
// Run:  geomesh t3.geo -2          (writes t3.msh)

w = 1.0;          // channel width
leg = 3.0;        // length of each leg, before the corner
across = 11;      // nodes across the channel (10 cells)
along = 16;       // nodes along each leg (15 cells)

// The channel: inlet along x, a w x w corner, outlet along y. Transfinite curves ignore
// point sizes, so only the two points the plenum shares (7 and 8) need one.
lc = 0.15;        // element size in the plenum

Point(1) = {0, 0, 0};
Point(2) = {leg, 0, 0};
Point(3) = {leg + w, 0, 0};
Point(4) = {leg + w, w, 0};
Point(5) = {leg, w, 0};
Point(6) = {0, w, 0};
Point(7) = {leg + w, w + leg, 0, lc};
Point(8) = {leg, w + leg, 0, lc};

Line(1) = {1, 2};    // inlet leg, bottom wall
Line(2) = {2, 3};    // corner, bottom wall
Line(3) = {3, 4};    // corner, outer wall
Line(4) = {4, 7};    // outlet leg, right wall
Line(5) = {7, 8};    // end of the outlet, into the plenum
Line(6) = {8, 5};    // outlet leg, left wall
Line(7) = {5, 6};    // inlet leg, top wall
Line(8) = {6, 1};    // the inlet
Line(9) = {2, 5};    // inlet | corner
Line(10) = {5, 4};   // corner | outlet

Curve Loop(1) = {1, 9, 7, 8};      Plane Surface(1) = {1};    // inlet leg
Curve Loop(2) = {2, 3, -10, -9};   Plane Surface(2) = {2};    // corner
Curve Loop(3) = {10, 4, 5, 6};     Plane Surface(3) = {3};    // outlet leg

// Across the channel: a Bump puts small cells against both walls, where the flow's
// boundary layer is, and larger ones in the middle. Every curve across the channel carries
// the same count, so that the grids of neighbouring blocks meet node to node.
Transfinite Curve{8, 9, 3, 2, 10, 5} = across Using Bump 0.25;

// Along the legs: a Progression makes each cell 0.88 times as long as the one before,
// going in the curve's direction. Both legs get finer towards the corner, where the flow
// turns; a minus sign reverses a curve for this purpose (line 7 runs away from the corner,
// -7 towards it).
Transfinite Curve{1, -7, -4, 6} = along Using Progression 0.88;

// A transfinite surface maps a grid onto its four sides (its corners are found from the
// boundary here; they can also be given: Transfinite Surface{1} = {1, 2, 5, 6}). Without
// recombination each grid cell is cut into two triangles; Recombine keeps the cells whole.
Transfinite Surface{1:3};
Recombine Surface{1:3};

// The plenum: a rectangle above the outlet with a pin of radius 0.4 in it. Its points carry
// a size, as in tutorial 1; its bottom edge is the outlet's end, already divided above.
Point(9) = {leg + 2 * w, w + leg, 0, lc};
Point(10) = {leg + 2 * w, 2 * w + leg + 1.5, 0, lc};
Point(11) = {leg - w, 2 * w + leg + 1.5, 0, lc};
Point(12) = {leg - w, w + leg, 0, lc};
Line(11) = {7, 9};
Line(12) = {9, 10};
Line(13) = {10, 11};  // the outlet of the whole part
Line(14) = {11, 12};
Line(15) = {12, 8};
Curve Loop(4) = {11, 12, 13, 14, 15, -5};

cx = leg + w / 2;
cy = w + leg + 1.4;
r = 0.4;
lcPin = 0.08;
Point(20) = {cx, cy, 0, lcPin};
Point(21) = {cx + r, cy, 0, lcPin};
Point(22) = {cx, cy + r, 0, lcPin};
Point(23) = {cx - r, cy, 0, lcPin};
Point(24) = {cx, cy - r, 0, lcPin};
Circle(21) = {21, 20, 22};
Circle(22) = {22, 20, 23};
Circle(23) = {23, 20, 24};
Circle(24) = {24, 20, 21};
Curve Loop(5) = {21:24};
Plane Surface(4) = {4, 5};

// Algorithm 8 (Frontal-Delaunay for quads) places points so that triangles pair up into
// right-angled quadrangles; Recombine does the pairing. Transfinite surfaces ignore the
// algorithm: their grid is fixed.
Mesh.Algorithm = 8;
Recombine Surface{4};

Physical Surface("fluid", 1) = {1:4};
Physical Curve("inlet", 2) = {8};
Physical Curve("outlet", 3) = {13};
Physical Curve("wall", 4) = {1, 2, 3, 4, 6, 7, 11, 12, 14, 15};
Physical Curve("pin", 5) = {21:24};
