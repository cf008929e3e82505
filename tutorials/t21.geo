// geomesh tutorial 21: a volume mesh from a triangulated surface (STL).
//
// Parts often arrive as triangulations rather than CAD: an STL file from a design tool or a
// 3D scanner, or the skin of an older mesh. t21_knob.stl is the skin of a control knob, a
// round shaft under a grip with a slot cut across its top, in 2060 triangles. The file
// names no curves and no points: once merged, it is one discrete surface, surface 1,
// which has no geometry of its own, only its triangles. A solver needs the inside filled
// with tetrahedra; this script asks for that and nothing more.
//
// Run:  geomesh t21.geo -3                          (writes t21.msh)
//       geomesh t21.geo -3 -setnumber size 0.04     (finer tetrahedra inside)

DefineConstant[
  size = {0.1, Min 0.02, Max 0.5, Name "Mesh/largest tetrahedron size"}
];

// Merge reads the file next to this script. STL, PLY, OFF and the other mesh formats geomesh
// reads become discrete surfaces this way when they hold surfaces only; an STL file
// with several `solid` sections gives one surface per section, numbered from 1 in order.
Merge "t21_knob.stl";

// A discrete surface can bound a volume like any other surface. Its triangles are kept as
// they are in the file: they are the volume's boundary mesh, and the tetrahedra's faces on
// the skin are exactly those triangles. They must close: a surface with holes cannot bound
// a volume, and geomesh then names the first free edge.
Surface Loop(1) = {1};
Volume(1) = {1};

// Inside, the tetrahedra grade from the sizes of the boundary triangles (each node of the
// skin asks for the mean length of its edges) up to Mesh.MeshSizeMax.
Mesh.MeshSizeMax = size;

Physical Surface("skin", 1) = {1};
Physical Volume("knob", 2) = {1};

// What a discrete surface cannot do: move, copy or extrude (Translate, Rotate, Duplicata,
// Extrude of surface 1 are errors, since there is no geometry to move, only triangles).
// For a volume around the part, as for a flow around it, build a box with the built-in
// kernel and give Volume both loops: Volume(2) = {box, 1}.
