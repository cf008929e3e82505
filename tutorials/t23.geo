// geomesh tutorial 23: meshing across the seams of a CAD model (compounds).
//
// CAD models often arrive cut into more faces than the part has: a face split by a leftover
// strip a few hundredths wide, an edge broken into pieces where that strip touches it. Each
// face is meshed on its own, so a strip 0.015 wide gets triangles 0.015 wide, however large
// the elements asked for: thin triangles, poor tetrahedra above them. `Compound Surface{..}`
// and `Compound Curve{..}` tell the mesher to treat several faces or edges as one.
//
// Here: a plate 2 x 1 x 0.2 with a round hole, whose top face was cut by such a strip.
//
// Run:  geomesh t23.geo -3                            (writes t23.msh)
//       geomesh t23.geo -3 -setnumber compound 0      (the same without compounds: the strip
//                                                      shows, the worst element is worse)

SetFactory("OpenCASCADE");

DefineConstant[
  size = {0.1, Min 0.02, Max 0.5, Name "Mesh/element size"},
  compound = {1, Choices{0, 1}, Name "Mesh/mesh the top across its seams"}
];

Box(1) = {0, 0, 0, 2, 1, 0.2};
Cylinder(2) = {1.4, 0.5, 0, 0, 0, 0.2, 0.2};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }

// The strip: a thin rectangle on the top face, fragmented into the plate. The top face is now
// three faces (the strip and one on each side of it), and the top edges of the front and back
// faces are each broken in three.
Rectangle(100) = {0.6, 0, 0.2, 0.015, 1};
BooleanFragments{ Volume{1}; Delete; }{ Surface{100}; Delete; }

// The entities lying in thin boxes: the faces of the top, the edges along its front and back.
top() = Surface In BoundingBox{-0.01, -0.01, 0.19, 2.01, 1.01, 0.21};
front() = Curve In BoundingBox{-0.01, -0.01, 0.19, 2.01, 0.01, 0.21};
back() = Curve In BoundingBox{-0.01, 0.99, 0.19, 2.01, 1.01, 0.21};

// A compound surface: its faces are first meshed one by one, finer than asked (by
// Mesh.CompoundMeshSizeFactor, 0.5), those triangles are mapped together onto the plane, and
// the map is meshed once at the sizes asked; the seams between the faces get no nodes. The
// triangles then go back to the face they lie in (each keeps its face's side), and the nodes
// onto their face's own shape, so the physical group "top" below still holds the whole top.
// A compound curve is meshed as one curve running through its curves end to end.
//
// What cannot be a compound is said in a warning, and its entities are meshed one by one: a
// compound surface whose inner curves also bound a face outside it, or whose faces do not map
// to the plane (a closed surface: split it), curves that do not make one chain.
If (compound)
  Compound Surface{top()};
  Compound Curve{front()};
  Compound Curve{back()};
EndIf

Mesh.MeshSizeMax = size;

Physical Surface("top", 1) = top();
Physical Volume("plate", 2) = {1};
