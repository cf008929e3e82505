// t9: a hub flange meshed with quadratic tetrahedra that follow its round surfaces.
//
// Solvers for solids and many others want elements of order 2 or more: a 10-node
// tetrahedron has a node in the middle of each edge, and when that edge lies on a curved
// surface, the node lies on the surface too, so the element is curved like the part. This
// flange is a disk with a hub, a bore and a ring of bolt holes: nearly every face is round.

SetFactory("OpenCASCADE");

DefineConstant[ order = 2, holes = 6, size = 0.14 ];

Cylinder(1) = {0, 0, 0, 0, 0, 0.3, 1.0};    // the flange plate
Cylinder(2) = {0, 0, 0, 0, 0, 1.0, 0.45};   // the hub on top of it
flange() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };

tools() = {};
For i In {0 : holes - 1}
  angle = 2 * Pi * i / holes;
  tools() += newv;
  Cylinder(newv) = {0.72 * Cos(angle), 0.72 * Sin(angle), -0.1, 0, 0, 0.5, 0.09};
EndFor
tools() += newv;
Cylinder(newv) = {0, 0, -0.1, 0, 0, 1.3, 0.25};   // the bore through the hub
flange() = BooleanDifference{ Volume{flange(0)}; Delete; }{ Volume{tools()}; Delete; };

Mesh.MeshSizeMax = size;

// The order of the elements. Mesh.ElementOrder (or -order on the command line) makes every
// element of the mesh quadratic (2), cubic (3) or quartic (4) once the first-order mesh is
// done: lines, triangles and tetrahedra get nodes on their edges (and faces, and insides
// from order 3). The new nodes on a curve or a surface are put on its geometry;
// Mesh.SecondOrderLinear = 1 would keep them on the straight edges instead.
Mesh.ElementOrder = order;

// A curved element can fold over itself where a coarse element meets a strongly curved
// surface. Every curved element is checked (the sign of its Jacobian, bounded over the
// whole element, not only at its nodes). With Mesh.HighOrderOptimize > 0 the curvature of
// the boundary is first spread into the free nodes inside the volume around the poor ones;
// an element that stays folded is straightened, with a warning. The summary at the end
// prints the smallest scaled Jacobian of the mesh: above 0, every element is valid.
Mesh.HighOrderOptimize = 2;

// Mesh.SecondOrderIncomplete = 1 asks for serendipity elements where a family has them
// (8-node quadrangles, 20-node hexahedra); tetrahedra of order 2 have no other form.

Physical Volume("flange") = {flange(0)};
e = 1e-3;
Physical Surface("bore") = Surface In BoundingBox{-0.26, -0.26, -e, 0.26, 0.26, 1 + e};
Physical Surface("seat") = Surface In BoundingBox{-1 - e, -1 - e, -e, 1 + e, 1 + e, e};
