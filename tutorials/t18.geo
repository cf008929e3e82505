// geomesh tutorial 18: sizes and quality inside volumes.
//
// A block with a bore, glued to a lid, meshed with tetrahedra. The surfaces set the sizes at
// the boundary; inside the volumes the tetrahedra follow them, graded between, unless a size
// field asks for something else. Here a Ball field refines a zone in the middle of the block
// that touches no surface: only the volume mesher sees it.
//
// Run:  geomesh t18.geo -3          (writes t18.msh)

SetFactory("OpenCASCADE");

// The block with a bore along z, and a lid on top of it. The lid is made on its own, so its
// bottom face and the block's top face are two faces at the same place: BooleanFragments
// makes them one face shared by both volumes, whose tetrahedra then meet node to node.
// (Leave it out and geomesh warns that volumes 1 and 2 touch without sharing a surface.)
Box(1) = {0, 0, 0, 2, 1, 1};
Cylinder(2) = {1.5, 0.5, 0, 0, 0, 1, 0.2};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Box(4) = {0, 0, 1, 2, 1, 0.3};
BooleanFragments{ Volume{3, 4}; Delete; }{}

// Sizes at the boundary: 0.12 everywhere, finer on the bore.
Mesh.MeshSizeMax = 0.12;
bore() = Surface In BoundingBox{1.25, 0.25, -0.01, 1.75, 0.75, 1.01};
MeshSize{ PointsOf{ Surface{bore()}; } } = 0.04;

// A zone of size 0.03 around (0.5, 0.5, 0.5), growing to the boundary's sizes beyond 0.35.
// Mesh.MeshSizeExtendFromBoundary (on by default) lets the sizes interpolated from the
// boundary bound the field's; set it to 0 and the field alone sets the sizes inside.
Field[1] = Ball;
Field[1].XCenter = 0.5;
Field[1].YCenter = 0.5;
Field[1].ZCenter = 0.5;
Field[1].Radius = 0.2;
Field[1].Thickness = 0.15;
Field[1].VIn = 0.03;
Field[1].VOut = 1;
Background Field = 1;

// The volume mesher: Delaunay refinement of the boundary's tetrahedra. Mesh.Algorithm3D 1
// (Delaunay), 4 (Frontal) and 10 (HXT) all name it. Mesh.Optimize then smooths the inner
// nodes and swaps faces, removes edges and moves nodes around every tetrahedron whose gamma
// (1 for a regular one) is below Mesh.OptimizeThreshold, or 0.45 when the threshold is lower.
// The summary at the end gives the worst and mean gamma.
Mesh.Algorithm3D = 1;
Mesh.Optimize = 1;
Mesh.OptimizeThreshold = 0.3;

Physical Volume("block", 1) = {3};
Physical Volume("lid", 2) = {4};
Physical Surface("bore", 3) = {bore()};
