// geomesh tutorial 15: views: a size map read from a file, plugins, views written back.
//
// A view is a set of values on points, lines, triangles, ... tetrahedra, which a solver or
// another script wrote. geomesh reads views from .pos files (the parsed format read here,
// and the older list-based format) and from the data sections of .msh files. A view of
// scalar values can set the mesh sizes: `Background Mesh View[n]` makes the value
// interpolated at a point the size wanted there. Plugins compute new views from a view or
// from the mesh; `Save View[n]` writes one to a .pos or .msh file.
//
// Run:  geomesh t15.geo -2          (writes t15.msh)

// View 0: the target sizes, h = 0.02 + 0.05 x, fine on the left of the plate.
Merge "t15_sizes.pos";

// A plate of 2 x 1 with a round hole. The points carry no size: the view gives them all.
Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 1, 0};
Point(4) = {0, 1, 0};
Point(5) = {1.2, 0.5, 0};
Point(6) = {1.4, 0.5, 0};
Point(7) = {1.0, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6};
Plane Surface(1) = {1, 2};
Physical Surface("plate", 1) = {1};

// Sizes from the view only: neither the points nor the boundary add theirs.
Background Mesh View[0];
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh 2;

// Each triangle's size as a view of its own (ElementSize: the edge of the equilateral
// triangle of the same area), then the ratio of that size to the target at each node:
// MathEval reads the nodes' coordinates x, y and the view's values v0.
Plugin(ElementSize).Run;
Plugin(MathEval).View = 1;
Plugin(MathEval).Expression0 = "v0 / (0.02 + 0.05 * x)";
Plugin(MathEval).Run;
View[2].Name = "size / target";

// The mean of that ratio over the plate: Integrate sums it over the triangles, and the
// integral of 1 (a MathEval view of ones) is the plate's area.
Plugin(Integrate).View = 2;
Plugin(Integrate).Run;
Plugin(MathEval).View = 1;
Plugin(MathEval).Expression0 = "1";
Plugin(MathEval).Run;
Plugin(Integrate).View = 4;
Plugin(Integrate).Run;
ratio = View[3].Max / View[5].Max;
Printf("views: %g", PostProcessing.NbViews);
Printf("plate area: %.4f", View[5].Max);
If (ratio > 0.8 && ratio < 1.25)
  Printf("the triangles follow the size map: mean size / target within 0.8 to 1.25");
EndIf

// The ratio cut along the line y = 0.25 (a plane through it): a view of line elements.
Plugin(CutPlane).A = 0;
Plugin(CutPlane).B = 1;
Plugin(CutPlane).C = 0;
Plugin(CutPlane).D = -0.25;
Plugin(CutPlane).View = 2;
Plugin(CutPlane).Run;
If (View[6].NbElements > 10)
  Printf("the cut along y = 0.25 holds line elements");
EndIf

// Views can be written (next to this script): .pos files are read back by Merge.
// Save View[2] "t15_ratio.pos";
