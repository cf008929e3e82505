// LineGeometry: a straight segment parametrized over [0, 1].
#pragma once

#include "kernel/geometry.h"

namespace geomesh {

// A straight segment from `start` (t = 0) to `end` (t = 1).
class LineGeometry final : public CurveGeometry {
 public:
  LineGeometry(Vec3 start, Vec3 end) : start_(start), end_(end) {}

  Interval range() const override { return {0, 1}; }
  Vec3 point(double t) const override { return start_ + t * (end_ - start_); }
  Vec3 firstDerivative(double) const override { return end_ - start_; }
  Vec3 secondDerivative(double) const override { return {}; }
  CurveKind kind() const override { return CurveKind::Line; }

  // Parameter of the point of the (infinite) line closest to p.
  double project(Vec3 p) const;

 private:
  Vec3 start_, end_;
};

}  // namespace geomesh
