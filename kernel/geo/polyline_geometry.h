// PolylineGeometry: a chain of straight segments (Line with more than two points).
#pragma once

#include <vector>

#include "kernel/geometry.h"

namespace geomesh {

// Straight segments through `points` in order, parametrized over [0, 1] by the length run
// along them (each segment gets the share of the parameter its length has of the whole).
class PolylineGeometry final : public CurveGeometry {
 public:
  explicit PolylineGeometry(std::vector<Vec3> points);

  Interval range() const override { return {0, 1}; }
  Vec3 point(double t) const override;
  Vec3 firstDerivative(double t) const override;
  Vec3 secondDerivative(double) const override { return {}; }

 private:
  std::size_t segmentAt(double t) const;  // index i of the segment [points_[i], points_[i+1]]

  std::vector<Vec3> points_;
  std::vector<double> starts_;  // parameter at each point: 0 .. 1
};

}  // namespace geomesh
