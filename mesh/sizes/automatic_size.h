// AutomaticSize: the AutomaticMeshSizeField, sizes from curvature and thin gaps, graded.
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/model.h"

namespace geomesh {

// The AutomaticMeshSizeField, read isotropically. The reference computes it on an octree with
// external libraries; geomesh computes what its options define from the model directly:
//  - hBulk: the size wherever nothing else asks for less (when not positive, the model's
//    default size: a tenth of its bounding box's diagonal, as for points without a size);
//  - nPointsPerCircle: on curves and curved surfaces of curvature k, sources of size
//    2 Pi / (nPointsPerCircle k) (the largest principal curvature on surfaces);
//  - features, nPointsPerGap: a thin gap of width w between two boundary entities that share
//    no boundary and face each other (the closest point of one lies along the other's normal)
//    asks for w / nPointsPerGap at both sides: between surfaces in a model with volumes,
//    between curves in a 2D model (the reference looks for gaps in 3D only);
//  - gradation: the size grows away from each source by (gradation - 1) times the distance,
//    h(x) = min(hBulk, min over sources of (h_s + (gradation - 1) |x - x_s|));
//  - hMin, hMax: when positive, the final bounds on the size.
// Sources lie on sampled points of the model's curves and surfaces (about four per hBulk).
class AutomaticSize {
 public:
  struct Options {
    double hBulk = -1;
    double hMin = -1;
    double hMax = -1;
    double gradation = 1.1;
    bool features = true;
    int pointsPerCircle = 20;
    int pointsPerGap = 2;
  };
  AutomaticSize(const Model& model, const Options& options);

  double at(Vec3 p) const;
  double bulkSize() const { return bulk_; }
  std::size_t sourceCount() const { return sources_.size(); }

  struct Source {
    Vec3 point;
    double size;
  };

 private:
  void build(std::uint32_t begin, std::uint32_t end);
  void search(Vec3 p, std::uint32_t begin, std::uint32_t end, double& best) const;
  // A lower bound on the graded size any source of the subtree gives at p.
  double bound(Vec3 p, std::uint32_t node) const;

  Options options_;
  double bulk_ = 1;
  double rate_ = 0.1;
  // A k-d tree in one array, as PointCloud's; each subtree's box and smallest size are kept
  // at its middle element.
  std::vector<Source> sources_;
  std::vector<Vec3> boxMin_, boxMax_;
  std::vector<double> smallest_;
  std::vector<std::uint8_t> axis_;
};

// The sources of an AutomaticMeshSizeField (exposed for tests): curvature and gap sources,
// each asking for less than `bulk`.
std::vector<AutomaticSize::Source> automaticSizeSources(const Model& model,
                                                        const AutomaticSize::Options& options,
                                                        double bulk);

}  // namespace geomesh
