#pragma once

#include "kernel/model.h"
#include "mesh/mesh_options.h"

namespace geomesh {

// How the target element size is derived from the model and the Mesh.* options: a point's
// prescribed size (or the model's default size) is interpolated along curves, then clamped
// into [sizeMin, sizeMax] and multiplied by sizeFactor.
struct SizeRules {
  double sizeMin = 0;
  double sizeMax = 1e22;
  double factor = 1;
  double defaultSize = 1;  // a tenth of the model's bounding box diagonal
  bool fromPoints = true;

  static SizeRules from(const Model& model, const MeshOptions& options);
  // The size a point asks for before clamping: its own when it has one, else the default.
  double pointSize(const ModelPoint& p) const;
  // Clamps a raw size and applies the factor.
  double finish(double rawSize) const;
};

}  // namespace geomesh
