// BoundaryExtension: the Extend field's boundary edges, and its law carrying their sizes inwards.
#pragma once

#include <memory>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh_options.h"

namespace geomesh {

class PointCloud;

// The Extend size field. Its boundary is made of edges: those of the 1D mesh of the listed
// curves, placed as the 1D stage places nodes from the end points' sizes and `options`
// (without the bounds a background field or curvature may add there),
// and, for the listed surfaces, edges standing for their mesh: at points sampled on a
// parameter grid, whose length is what the law below gives there from the surface's own
// curves. A point at distance d from the midpoint of the nearest edge, of length SizeBnd,
// gets f SizeBnd + (1 - f) sizeMax with f = ((distMax - d) / distMax)^power when d < distMax,
// and sizeMax beyond. Inside surfaces the curves' edges count, inside volumes the surfaces';
// on points and curves, and where there are no such edges, the field asks for nothing (1e22).
class BoundaryExtension {
 public:
  struct Law {
    double distMax = 1;
    double power = 1;
    double sizeMax = 1;
  };
  BoundaryExtension(const Model& model, const std::vector<int>& curves,
                    const std::vector<int>& surfaces, Law law, const MeshOptions& options);
  ~BoundaryExtension();

  // The size at p, in an entity of dimension `dim`.
  double at(Vec3 p, int dim) const;

  // Edges by their midpoints.
  struct Edges {
    std::unique_ptr<PointCloud> midpoints;
    std::vector<double> lengths;
    double at(Vec3 p, const Law& law) const;
  };

 private:
  Law law_;
  Edges curveEdges_;
  Edges surfaceEdges_;
};

}  // namespace geomesh
