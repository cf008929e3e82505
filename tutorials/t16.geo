// geomesh tutorial 16: adapting a mesh to an error estimate, for a given number of elements.
//
// A solver computes a solution on a mesh and estimates the error on each element. The best
// mesh for a budget of N elements spreads the error evenly: small elements where the
// estimate is large, big ones where it is small. The Adapt field turns a view of
// per-element error estimates into the sizes of that mesh (the README gives its
// formulas); meshing again with it as the background field, then estimating
// again, is the adaptation loop. Here the "solver" is a formula: the function
// u = exp(-50 r^2), a bump centred at (0.6, 0.4), interpolated linearly on triangles, whose
// error on an element of size h is about h^2 |second derivative of u| on a measure ~h^2.
//
// Run:  geomesh t16.geo -2          (writes t16.msh)

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("square", 1) = {1};

// Sizes from the fields only; the first mesh is uniform, of size 0.05.
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeMax = 0.05;

target = 4000;   // triangles wanted
asked = target;  // what the field is asked for, corrected from pass to pass

For pass In {1:5}
  Mesh 2;
  Printf("pass %g: %g triangles", pass, Mesh.NbTriangles);
  // The field's count is a prediction: the mesher places a few more or fewer triangles.
  // Asking for target * (asked / obtained) next time closes the gap within a few passes.
  If (pass > 1)
    asked = asked * target / Mesh.NbTriangles;
  EndIf
  Mesh.MeshSizeMax = 0.3;

  // The error estimate on each triangle: ElementSize gives its size h (one value on each of
  // its nodes), MathEval the estimate h^3 |u''| at each node (h^2 |u''| times the square
  // root of the triangle's area, about h), which Adapt averages over the triangle.
  Plugin(ElementSize).Run;
  Plugin(MathEval).View = PostProcessing.NbViews - 1;
  Plugin(MathEval).Expression0 = "v0^3 * 100 * Exp(-50 * ((x-0.6)^2 + (y-0.4)^2)) * (1 + Abs(100 * ((x-0.6)^2 + (y-0.4)^2) - 1))";
  Plugin(MathEval).Run;

  // Sizes for `asked` triangles: errors converging as h^Order (pointwise) on each element.
  Field[1] = Adapt;
  Field[1].View = PostProcessing.NbViews - 1;
  Field[1].Order = 2;
  Field[1].TargetElements = asked;
  Field[1].SizeMax = 0.3;
  Background Field = 1;
EndFor

Mesh 2;
Printf("final: %g triangles", Mesh.NbTriangles);
If (Fabs(Mesh.NbTriangles - target) < 0.05 * target)
  Printf("the triangle count is within 5 percent of the target");
EndIf
