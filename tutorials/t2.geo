// geomesh tutorial 2: element sizes, from the coarsest control to the finest.
//
// A mounting bracket: a flat plate with rounded corners, a bolt hole and a clamped strip
// along its right edge. Four ways of saying how large elements should be, each on top of
// the previous one:
//   1. a size on each point, interpolated along the curves and into the surface;
//   2. sizes from curvature: a number of elements per full turn on every arc;
//   3. size fields: functions of space that give the size anywhere. A Distance field
//      measures how far we are from the hole, a Threshold field turns that distance into
//      a size, a Box field refines the clamped strip and a Min field keeps the smaller of
//      the two. `Background Field` says which field the mesher uses;
//   4. the global factor -clscale, from the command line, which scales every size at once.
// The mesher takes, at each place, the smallest of the sizes that apply there.
//
// Run:  geomesh t2.geo -2                  (writes t2.msh)
//       geomesh t2.geo -2 -clscale 0.5     (every element half as large: about 4x as many)

length = 4.0;     // the plate
width = 2.0;
fillet = 0.4;     // radius of the rounded corners
holeX = 1.2;      // the bolt hole
holeY = 1.0;
holeR = 0.3;
coarse = 0.25;    // size far from every feature

// 1. Point sizes. Every point of the plate asks for the coarse size; the points of the
// hole ask for the same: the hole is refined by the fields below, not here.

// The outline: four straight edges joined by four quarter circles. Each corner arc has
// its own centre point, which is not part of the mesh but carries the arc's geometry.
Point(1) = {fillet, 0, 0, coarse};
Point(2) = {length - fillet, 0, 0, coarse};
Point(3) = {length, fillet, 0, coarse};
Point(4) = {length, width - fillet, 0, coarse};
Point(5) = {length - fillet, width, 0, coarse};
Point(6) = {fillet, width, 0, coarse};
Point(7) = {0, width - fillet, 0, coarse};
Point(8) = {0, fillet, 0, coarse};
Point(9) = {length - fillet, fillet, 0, coarse};          // arc centres
Point(10) = {length - fillet, width - fillet, 0, coarse};
Point(11) = {fillet, width - fillet, 0, coarse};
Point(12) = {fillet, fillet, 0, coarse};

Line(1) = {1, 2};                 // bottom
Circle(2) = {2, 9, 3};            // Circle(tag) = {start, centre, end}: an arc under 180 deg
Line(3) = {3, 4};                 // right: the clamped edge
Circle(4) = {4, 10, 5};
Line(5) = {5, 6};                 // top
Circle(6) = {6, 11, 7};
Line(7) = {7, 8};                 // left
Circle(8) = {8, 12, 1};

// The bolt hole: a full circle needs at least two arcs (each must be under 180 degrees);
// four quarters keep every arc well shaped.
Point(20) = {holeX, holeY, 0, coarse};
Point(21) = {holeX + holeR, holeY, 0, coarse};
Point(22) = {holeX, holeY + holeR, 0, coarse};
Point(23) = {holeX - holeR, holeY, 0, coarse};
Point(24) = {holeX, holeY - holeR, 0, coarse};
Circle(21) = {21, 20, 22};
Circle(22) = {22, 20, 23};
Circle(23) = {23, 20, 24};
Circle(24) = {24, 20, 21};

Curve Loop(1) = {1:8};            // a range: 1, 2, ..., 8
Curve Loop(2) = {21:24};
Plane Surface(1) = {1, 2};

// 2. Sizes from curvature: 16 elements per full turn on every curved edge. On an arc of
// radius r this asks for a size of 2*Pi*r/16, so the small corner arcs and the hole get
// finer elements than the straight edges, with no size written anywhere.
Mesh.MeshSizeFromCurvature = 16;

// 3. Size fields.
// Field 1 is the distance to the hole's four arcs (each sampled at 40 points).
Field[1] = Distance;
Field[1].CurvesList = {21:24};
Field[1].Sampling = 40;

// Field 2 turns that distance into a size: SizeMin up to DistMin from the hole, SizeMax
// beyond DistMax, and a linear ramp between. Stress concentrates around a bolt hole, so
// that is where the solver needs small elements.
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.03;
Field[2].SizeMax = coarse;
Field[2].DistMin = 0.05;
Field[2].DistMax = 0.6;

// Field 3 refines the clamped strip along the right edge: VIn inside the box, VOut outside
// it; Thickness makes the size grow smoothly over 0.3 around the box instead of jumping.
Field[3] = Box;
Field[3].VIn = 0.06;
Field[3].VOut = coarse;
Field[3].XMin = length - 0.3;
Field[3].XMax = length;
Field[3].YMin = 0;
Field[3].YMax = width;
Field[3].Thickness = 0.3;

// Field 4 is the smaller of fields 2 and 3 at each point; it is the one the mesher uses.
Field[4] = Min;
Field[4].FieldsList = {2, 3};
Background Field = 4;

Physical Surface("bracket", 1) = {1};
Physical Curve("clamped", 2) = {3};
Physical Curve("bolt", 3) = {21:24};
