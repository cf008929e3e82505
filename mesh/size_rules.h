#pragma once

#include <utility>

#include "kernel/model.h"
#include "mesh/mesh_options.h"

namespace geomesh {

// How the target element size is derived from the model and the Mesh.* options: the sizes
// prescribed at a curve's end points are interpolated along it, then clamped into
// [sizeMin, sizeMax] and multiplied by sizeFactor. A curve with no size at either end gets
// the model's default size; one with a size at one end only is interpolated towards an
// unbounded size at the other (so it stays coarse, as in Gmsh).
struct SizeRules {
  double sizeMin = 0;
  double sizeMax = 1e22;
  double factor = 1;
  double defaultSize = 1;          // a tenth of the model's bounding box diagonal
  bool fromPoints = true;          // else points ask for nothing (sizeMax applies)
  bool extendFromBoundary = true;  // else surface interiors get sizeMax, not boundary sizes

  static SizeRules from(const Model& model, const MeshOptions& options);
  // The sizes a curve's end points ask for, before clamping.
  std::pair<double, double> curveEndSizes(const ModelPoint& start, const ModelPoint& end) const;
  // The size at a point's own node, before clamping: its size, else the default (unbounded
  // when fromPoints is off).
  double pointSize(const ModelPoint& p) const;
  // Clamps a raw size and applies the factor.
  double finish(double rawSize) const;
};

}  // namespace geomesh
