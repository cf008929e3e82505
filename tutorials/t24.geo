// geomesh tutorial 24: a noisy scan cleaned up before meshing: fairing, simplification and
// curvature of a merged triangulation.
//
// Tutorials 21 and 22 took an STL file as it came. Scans are rougher: t24_scan.stl is a ball
// of radius 2 as a scanner might see it, 2000 small triangles whose vertices lie up to 1% off
// the true surface (t24_scan.py wrote it). Meshed as it is, that noise would show in every
// element on the skin. Here the triangles are first smoothed (Fair) and thinned out
// (Simplify), with a look at the curvature before and after, and only then sorted into faces,
// given a geometry and meshed as in t22.
//
// Run:  geomesh t24.geo -3                                 (writes t24.msh)
//       geomesh t24.geo -3 -setnumber passes 0             (no fairing: see the curvature)
//       geomesh t24.geo -2 -check                          (the skin's topology, part by part)

DefineConstant[
  passes = {3, Min 0, Max 20, Step 1, Name "Scan/fairing iterations"},
  triangles = {800, Min 100, Max 2000, Name "Scan/triangles kept"},
  size = {0.25, Min 0.05, Max 1, Name "Mesh/element size"}
];

Merge "t24_scan.stl";

// Plugin(Curvature) makes a view of the mean curvature at every node of the current surface:
// the session's mesh once there is one, else (as here) the merged triangles. Type = 1 gives
// the Gaussian curvature, Type = 2 the largest principal curvature. On a ball of radius 2 the
// mean curvature is 1/2 everywhere; the noise of the scan makes it swing far from that, since
// curvature is measured over single triangles (view 0).
Plugin(Curvature).Run;
Printf("mean curvature of the scan: %.1f to %.1f", View[0].Min, View[0].Max);

// Plugin(Fair) smooths the triangles by mean-curvature flow: each iteration moves every node
// a step along the surface's curvature, which flattens bumps much faster than it changes the
// overall shape (a closed surface is scaled back to the volume it enclosed). TimeStep sets
// the step, in units of the squared mean edge length (0.5 unless told). Nodes on open borders
// stay put. No triangle is added or removed.
If (passes > 0)
  Plugin(Fair).Iterations = passes;
  Plugin(Fair).Run;
EndIf

// Plugin(Simplify) collapses edges, the cheapest first (the one whose merged node stays
// closest to the planes of the triangles it replaces), until TargetTriangles are left or, with
// MaxError, until the next collapse would move the surface farther than that distance. A
// faired surface simplifies well: its triangles are big where it is flat.
Plugin(Simplify).TargetTriangles = triangles;
Plugin(Simplify).Run;

// The curvature of what is left (view 1): close to 1/2, the noise gone.
Plugin(Curvature).Run;
Printf("mean curvature after fairing and simplifying: %.1f to %.1f", View[1].Min, View[1].Max);

// From here on as in t22: the triangles are sorted into surfaces (a closed ball is cut into
// patches that map to the plane), each gets a geometry built from the cleaned-up triangles,
// and the skin is meshed anew at the size asked for, the ball filled with tetrahedra.
ClassifySurfaces{40 * Pi / 180, 1, 1, Pi};
CreateGeometry;

Surface Loop(1) = Surface{:};
Volume(1) = {1};
Mesh.MeshSizeMax = size;

Physical Surface("skin", 1) = Surface{:};
Physical Volume("ball", 2) = {1};
