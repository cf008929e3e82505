// geomesh tutorial 22: remeshing a triangulated surface (STL) at the sizes you choose.
//
// Tutorial 21 filled the knob of t21_knob.stl with tetrahedra and kept the file's 2060
// triangles as its skin: the skin was as fine as whoever wrote the file made it. Here the skin
// is meshed anew at the size the solver needs: first the triangles are sorted into faces (the
// shaft, the grip's side, its flat top, the slot's walls...), then each face gets a geometry
// built from its triangles, and from then on it is meshed like a surface of the built-in
// kernel: every 2D algorithm, sizes, fields.
//
// Run:  geomesh t22.geo -3                           (writes t22.msh)
//       geomesh t22.geo -3 -setnumber size 0.03      (a finer skin and volume)
//       geomesh t22.geo -2 -setnumber remesh 0       (the faces found, with the file's triangles)

DefineConstant[
  size = {0.06, Min 0.01, Max 0.3, Name "Mesh/element size"},
  angle = {30, Min 10, Max 90, Name "Classification/face angle (degrees)"},
  remesh = {1, Choices{0, 1}, Name "Classification/create a geometry and remesh"}
];

Merge "t21_knob.stl";

// ClassifySurfaces{angle, boundary, forReparametrization, curveAngle} cuts the merged
// triangles into surfaces wherever two neighbours meet at more than `angle` (radians). Where
// surfaces meet it makes curves, and points where curves meet (a closed curve, like the rim of
// the shaft, gets one point). With boundary = 1, the edges of an open surface and the seams
// between surfaces the file already had separate surfaces too; forReparametrization = 1 also
// splits every surface that is not a topological disk; curveAngle breaks curves where they
// turn by more than it (Pi: never). The file's surface 1 is replaced by surfaces 2, 3...
// Before cutting, coincident vertices are welded and triangles that disagree with their
// neighbours are turned round (a warning says how many).
ClassifySurfaces{angle * Pi / 180, 1, 0, Pi};

// CreateGeometry maps each surface one-to-one onto the plane (a flat face by projection, the
// others by a convex-combination map of their triangles onto a disk, holes filled for the
// map), and each curve becomes the chain of the file's edges it runs along. A surface that
// cannot be mapped (a closed one, one with a handle, one whose map folds) is split in two
// until every part maps. The new nodes all lie on the file's triangles, so the skin keeps the
// file's shape and area. Without it, the surfaces keep the file's triangles (remesh = 0).
If (remesh)
  CreateGeometry;
EndIf

// Surface{:} lists every surface: the new ones bound the knob.
Surface Loop(1) = Surface{:};
Volume(1) = {1};

// From here on, sizes work as for any model: here one size everywhere.
Mesh.MeshSizeMax = size;

Physical Surface("skin", 1) = Surface{:};
Physical Volume("knob", 2) = {1};
