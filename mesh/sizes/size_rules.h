// SizeRules: the target element size from point sizes, Mesh.* options and curvature.
#pragma once

#include <map>
#include <set>
#include <utility>

#include "kernel/model.h"
#include "mesh/core/mesh_options.h"

namespace geomesh {

// How the target element size is derived from the model and the Mesh.* options: the sizes
// prescribed at a curve's end points are interpolated along it, then clamped into
// [sizeMin, sizeMax] and multiplied by sizeFactor. A curve with no size at either end gets
// the model's default size; one with a size at one end only is interpolated towards an
// unbounded size at the other (so it stays coarse, as in Gmsh).
// With Mesh.MeshSizeFromCurvature = N, the size is also at most 2*Pi / (N * curvature) along
// each curve, and at each point's own node (the largest curvature of the curves ending there).
// A point's curvature bound is not interpolated along the curves it bounds: a closed curve
// would otherwise take the size of its sharpest end all along.
// The size of points without one: a tenth of the box's diagonal, an x or y extent of zero
// counting as twice the diagonal (as the reference measures models in the x-z plane or along
// one axis); 1 for an empty or single-point box.
double defaultSizeOf(const BoundingBox& box);

struct SizeRules {
  double sizeMin = 0;
  double sizeMax = 1e22;
  double factor = 1;
  double defaultSize = 1;          // defaultSizeOf(model.sizeBox())
  bool fromPoints = true;          // else points ask for nothing (sizeMax applies)
  bool extendFromBoundary = true;  // else surface interiors get sizeMax, not boundary sizes
  double elementsPerTwoPi = 0;     // Mesh.MeshSizeFromCurvature; 0: off
  int minCircleNodes = 7;          // per full turn of a circle or ellipse arc
  int minCurveNodes = 3;           // on curves that are neither straight nor arcs
  std::map<int, double> pointCurvatureSizes = {};  // point tag -> bound from curvature
  // Curves given an even number of segments, since an all-quadrangle mesh needs an even
  // number of boundary edges: those bounding a surface (not transfinite) recombined by the
  // Blossom algorithm (Mesh.RecombinationAlgorithm 1), as the reference does.
  std::set<int> evenCurves = {};
  // With the anisotropic 2D algorithm (Mesh.Algorithm 7), curves follow an anisotropic
  // background along their tangent (size 1/sqrt(t'Mt)), as that algorithm's surfaces do.
  bool curvesAlongMetric = false;

  static SizeRules from(const Model& model, const MeshOptions& options);
  // The sizes a curve's end points ask for, before clamping (their curvature bound aside).
  std::pair<double, double> curveEndSizes(const ModelPoint& start, const ModelPoint& end) const;
  // The size at a point's own node, before clamping: its size, else the default (unbounded
  // when fromPoints is off).
  double pointSize(const ModelPoint& p) const;
  // The bound curvature puts on the size where the curve's curvature is `curvature`.
  double curvatureSize(double curvature) const;
  // The bound curvature puts on the size at a point (unbounded when off).
  double curvatureBound(int pointTag) const;
  // Clamps a raw size and applies the factor.
  double finish(double rawSize) const;
  // The fewest segments a curve gets, however large the size: 1 on a straight segment,
  // minCircleNodes per full turn on circle and ellipse arcs, minCurveNodes - 1 on others.
  int minimumSegments(const CurveGeometry& g) const;
};

// The largest size that keeps a few elements across a full turn of a bend of the given
// curvature, where sizes up to `largest` were asked for (unbounded on a flat place). With
// fewer, a triangle wraps round the bend (a slender cylinder's girth, the sharp edge of a thin
// profile) and faces away from the surface at one of its corners. Curves bounding a surface
// and the surface's interior both keep to it. It never falls below a tenth of `largest`, so
// that a bend tightening without end cannot ask for endless refinement.
double bendSize(double curvature, double largest);

// Whether sizes up to `largest` could outgrow a bend of the given curvature: only then is the
// bend bound worth evaluating everywhere.
bool sizesOutgrowBend(double curvature, double largest);

// Whether a curve bounding the surface is degenerate (a pole: a cone's apex, a sphere's tip).
bool hasPole(const Model& model, const ModelSurface& surface);

// The curvature of a curve at parameter t: |c' x c''| / |c'|^3.
double curveCurvature(const CurveGeometry& g, double t);

// The largest principal curvature (in absolute value) of a surface at uv, from the change of
// its unit normal over a small parameter step; 0 where the normal is undefined (a pole).
double surfaceCurvature(const SurfaceGeometry& g, Vec2 uv);

}  // namespace geomesh
