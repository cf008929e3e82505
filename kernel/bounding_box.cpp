// BoundingBox, and the smallest box holding a curve, found by sampling and refining extrema.
#include "kernel/bounding_box.h"

#include <cmath>
#include <vector>

#include "kernel/geometry.h"

namespace geomesh {

void BoundingBox::include(Vec3 p) {
  min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
  max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
}

void BoundingBox::include(const BoundingBox& b) {
  if (b.empty()) return;
  include(b.min);
  include(b.max);
}

namespace {

double coordinate(Vec3 p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }

// The extreme value of one coordinate (sign +1: largest, -1: smallest) of the curve between
// parameters a and b, which bracket a single extremum: golden-section search.
double refineExtremum(const CurveGeometry& curve, int axis, double sign, double a, double b) {
  const double ratio = (std::sqrt(5.0) - 1) / 2;
  auto value = [&](double t) { return sign * coordinate(curve.point(t), axis); };
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = value(c), fd = value(d);
  for (int i = 0; i < 80 && b - a > 1e-15 * (1 + std::abs(a)); ++i) {
    if (fc > fd) {
      b = d, d = c, fd = fc;
      c = b - ratio * (b - a), fc = value(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + ratio * (b - a), fd = value(d);
    }
  }
  return sign * std::max(fc, fd);
}

}  // namespace

// Samples the curve, then refines every sampled local extremum of each coordinate.
BoundingBox curveBoundingBox(const CurveGeometry& curve) {
  constexpr int kSamples = 64;
  const Interval r = curve.range();
  std::vector<double> t;
  std::vector<Vec3> p;
  for (int i = 0; i <= kSamples; ++i) {
    t.push_back(r.min + (r.max - r.min) * i / kSamples);
    p.push_back(curve.point(t.back()));
  }
  BoundingBox box;
  for (Vec3 q : p) box.include(q);
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {1.0, -1.0})
      for (int i = 1; i < kSamples; ++i) {
        const double here = sign * coordinate(p[i], axis);
        if (here < sign * coordinate(p[i - 1], axis) || here < sign * coordinate(p[i + 1], axis))
          continue;
        const double best = refineExtremum(curve, axis, sign, t[i - 1], t[i + 1]);
        Vec3 extreme = p[i];
        (axis == 0 ? extreme.x : axis == 1 ? extreme.y : extreme.z) = best;
        box.include(extreme);
      }
  return box;
}

const BoundingBox& CurveGeometry::boundingBox() const {
  if (!box_) box_ = curveBoundingBox(*this);
  return *box_;
}

}  // namespace geomesh
