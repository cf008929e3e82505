// geomesh tutorial 14: size fields that follow the boundary mesh, a cone, and the shape itself.
//
// A clamp plate: a plate with a round hole and a slot close to its top edge, which leaves a
// thin ligament of material above the slot. Three size fields, combined by a Min field:
//   1. Extend: the lengths of the boundary's edges (fine round the hole, coarse elsewhere)
//      carried into the plate, growing towards SizeMax over DistMax, faster with a larger
//      Power: the sizes of the points reach inside without a Distance field per feature;
//   2. Frustum: a cone of small elements from the hole towards the right edge, where a crack
//      would run: between an inner and an outer radius at each end, the size goes from the
//      inner value to the outer one; outside the cone the field asks for nothing;
//   3. AutomaticMeshSizeField: sizes read from the shape alone: nPointsPerCircle elements per
//      full turn where the boundary bends, nPointsPerGap layers across thin parts (the
//      ligament above the slot, the slot itself), hBulk elsewhere, and nowhere a jump larger
//      than `gradation` from one element to the next.
// Mesh.MeshSizeExtendFromBoundary = 0 leaves the inside of the plate to the fields alone.
//
// Run:  geomesh t14.geo -2                         (writes t14.msh)
//       geomesh t14.geo -2 -setnumber automatic 0  (without the automatic field)

DefineConstant[ automatic = 1 ];

length = 4.0;     // the plate
width = 2.0;
holeX = 1.2;      // the hole
holeY = 0.9;
holeR = 0.3;
slotX = 2.2;      // the slot: its lower left corner, length and height
slotY = 1.78;
slotL = 1.2;
slotH = 0.1;
coarse = 0.25;

// The plate's outline, with coarse points.
Point(1) = {0, 0, 0, coarse};
Point(2) = {length, 0, 0, coarse};
Point(3) = {length, width, 0, coarse};
Point(4) = {0, width, 0, coarse};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};

// The hole: two half circles, with fine points (the Extend field carries their size).
Point(5) = {holeX, holeY, 0};
Point(6) = {holeX + holeR, holeY, 0, 0.04};
Point(7) = {holeX - holeR, holeY, 0, 0.04};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 6};
Curve Loop(2) = {5, 6};

// The slot, 0.12 below the top edge.
Point(8) = {slotX, slotY, 0, 0.1};
Point(9) = {slotX + slotL, slotY, 0, 0.1};
Point(10) = {slotX + slotL, slotY + slotH, 0, 0.1};
Point(11) = {slotX, slotY + slotH, 0, 0.1};
Line(7) = {8, 9};
Line(8) = {9, 10};
Line(9) = {10, 11};
Line(10) = {11, 8};
Curve Loop(3) = {7, 8, 9, 10};

Plane Surface(1) = {1, 2, 3};

// 1. Extend: the boundary's edge lengths, carried 0.6 inwards, with a quadratic law.
Field[1] = Extend;
Field[1].CurvesList = {1:10};
Field[1].DistMax = 0.6;
Field[1].SizeMax = coarse;
Field[1].Power = 2;

// 2. Frustum: from the hole's right side (size 0.02 on the axis) to the right edge (0.06),
// within 0.15 of the axis at the hole and 0.4 at the edge, where the size is back to coarse.
Field[2] = Frustum;
Field[2].X1 = holeX + holeR; Field[2].Y1 = holeY; Field[2].Z1 = 0;
Field[2].X2 = length; Field[2].Y2 = holeY; Field[2].Z2 = 0;
Field[2].InnerR1 = 0; Field[2].OuterR1 = 0.15;
Field[2].InnerR2 = 0; Field[2].OuterR2 = 0.4;
Field[2].InnerV1 = 0.02; Field[2].OuterV1 = coarse;
Field[2].InnerV2 = 0.06; Field[2].OuterV2 = coarse;

// 3. The automatic field: 40 elements per turn of the hole, 3 layers across thin parts.
Field[3] = AutomaticMeshSizeField;
Field[3].hBulk = coarse;
Field[3].nPointsPerCircle = 40;
Field[3].nPointsPerGap = 3;
Field[3].gradation = 1.2;

// The smallest of the three is the size; without the automatic field, of the first two.
Field[4] = Min;
If (automatic)
  Field[4].FieldsList = {1, 2, 3};
Else
  Field[4].FieldsList = {1, 2};
EndIf
Background Field = 4;
Mesh.MeshSizeExtendFromBoundary = 0;

Physical Surface("plate", 1) = {1};
