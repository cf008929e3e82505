// geomesh tutorial 20: boundary layers in a plane, from a BoundaryLayer field.
//
// A cooling fin standing on the floor of a flat channel, seen in section: air flows along x
// over the floor, climbs the fin and falls behind it. A 2D flow solver wants thin cells on
// the floor and on the fin, and coarse ones in the middle of the stream. In tutorial 19 a
// layer was made by extruding the walls; here the layer is asked of the surface mesher
// instead: a BoundaryLayer field names the walls, the first cell's height and the growth,
// and the mesher lays columns of cells along the walls' normals before it fills the rest of
// the surface with triangles from the layer's outer edge. Nothing is added to the geometry:
// the surface, its curves and its physical groups stay as they are.
//
// Run:  geomesh t20.geo -2                              (writes t20.msh)
//       geomesh t20.geo -2 -setnumber recombine 1       (quadrangles beyond the layer too)
//       geomesh t20.geo -2 -setnumber quads 0           (the layer's cells cut into triangles)

DefineConstant[
  firstHeight = {0.002, Min 0.0002, Max 0.02, Name "Layer/first cell height"},
  ratio = {1.2, Min 1, Max 2, Name "Layer/growth ratio"},
  thickness = {0.03, Min 0.005, Max 0.2, Name "Layer/thickness"},
  quads = {1, Choices {0, 1}, Name "Layer/quadrangles"},
  fan = {5, Min 1, Max 20, Step 1, Name "Layer/elements in the fans"},
  recombine = {0, Choices {0, 1}, Name "Mesh/recombine the rest"}
];

L = 1.6;        // channel length
H = 0.5;        // channel height
x0 = 0.5;       // the fin's upstream face
t = 0.08;       // fin thickness
h = 0.2;        // fin height
lcWall = 0.02;  // element size along the floor and the fin
lcFar = 0.06;   // element size on the ceiling, the inlet and the outlet

// The outline, counterclockwise: inlet corner, floor up to the fin, round the fin, floor
// to the outlet, then the ceiling back. The fin's two upper corners (points 4 and 5) are
// convex seen from the air; its feet (points 3 and 6) are concave.
Point(1) = {0, 0, 0, lcWall};
Point(2) = {L, 0, 0, lcWall};
Point(3) = {x0, 0, 0, lcWall};
Point(4) = {x0, h, 0, lcWall};
Point(5) = {x0 + t, h, 0, lcWall};
Point(6) = {x0 + t, 0, 0, lcWall};
Point(7) = {L, H, 0, lcFar};
Point(8) = {0, H, 0, lcFar};
Line(1) = {1, 3};   // floor, upstream
Line(2) = {3, 4};   // the fin's upstream face
Line(3) = {4, 5};   // its top
Line(4) = {5, 6};   // its downstream face
Line(5) = {6, 2};   // floor, downstream
Line(6) = {2, 7};   // outlet
Line(7) = {7, 8};   // ceiling
Line(8) = {8, 1};   // inlet
Curve Loop(1) = {1 : 8};
Plane Surface(1) = {1};

// The layer. CurvesList names the walls it grows from; Size is the first cell's height on
// the wall and Ratio the growth from one cell to the next, so the columns' nodes sit at
// Size, Size (1 + Ratio), ... from the wall, and stop before Thickness: with the defaults,
// 0.002, 0.0044, 0.00728, ... up to 0.0258, 7 cells below 0.03. Quads = 1 keeps each cell a
// quadrangle; 0 cuts it into two triangles.
//
// Where walls meet, the layer has to turn. At a concave corner (the fin's feet) the two
// walls' columns meet along the corner's bisector, and one column runs up it. At a convex
// corner (the top of the fin) the columns part and leave a wedge open: FanPointsList names
// the corners to fill with a fan of cells, FanPointsSizesList how many each gets (points
// missing from it get Mesh.BoundaryLayerFanElements). A convex corner left out of the list
// is filled with triangles by the rest of the mesh.
//
// At the inlet and the outlet the layer ends: a wall node next to a curve without a layer
// gets no column, so the floor's first and last segments are left to the triangles, and
// the inlet's and outlet's curves keep the sizes of their points.
Field[1] = BoundaryLayer;
Field[1].CurvesList = {1 : 5};
Field[1].Size = firstHeight;
Field[1].Ratio = ratio;
Field[1].Thickness = thickness;
Field[1].Quads = quads;
Field[1].FanPointsList = {4, 5};
Field[1].FanPointsSizesList = {fan, fan};
BoundaryLayer Field = 1;

// Beyond the layer the surface is meshed as usual; Recombine Surface recombines that part
// into quadrangles and leaves the layer's columns as they were built.
If (recombine)
  Recombine Surface{1};
EndIf

// Where the layer is too thick for the space it grows into, its columns are shortened so
// that its cells neither cross each other nor reach another wall, and geomesh says where.
// Here that happens at the fin's feet: the floor's columns next to the fin would run into
// the fin's layer, and the fin's into the floor's, so both are cut where they meet. The layer works in plane surfaces; a surface that is not plane is
// meshed without it, with a warning.

Physical Curve("wall", 1) = {1 : 5};
Physical Curve("inlet", 2) = {8};
Physical Curve("outlet", 3) = {6};
Physical Curve("ceiling", 4) = {7};
Physical Surface("air", 5) = {1};

// The run's summary gives the number of layer cells and the scaled Jacobian at their
// corners, 1 for a right-angled cell: along the straight walls the columns are square to
// the wall, and the fans' cells are the ones that fall below it.
