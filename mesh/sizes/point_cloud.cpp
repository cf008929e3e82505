// PointCloud: an array-stored k-d tree built by median splits, and its nearest-point search.
#include "mesh/sizes/point_cloud.h"

#include <algorithm>
#include <cmath>

namespace geomesh {
namespace {

double coordinate(Vec3 p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

double distance2(Vec3 a, Vec3 b) {
  const Vec3 d = a - b;
  return dot(d, d);
}

}  // namespace

PointCloud::PointCloud(std::vector<Vec3> points) : points_(std::move(points)) {
  axis_.assign(points_.size(), 0);
  build(0, static_cast<std::uint32_t>(points_.size()));
}

// Splits along the axis of largest extent of the range.
void PointCloud::build(std::uint32_t begin, std::uint32_t end) {
  if (end - begin <= 1) return;
  Vec3 lo = points_[begin], hi = lo;
  for (std::uint32_t k = begin; k < end; ++k) {
    const Vec3 q = points_[k];
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
  }
  const Vec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(points_.begin() + begin, points_.begin() + mid, points_.begin() + end,
                   [axis](Vec3 a, Vec3 b) { return coordinate(a, axis) < coordinate(b, axis); });
  axis_[mid] = static_cast<std::uint8_t>(axis);
  build(begin, mid);
  build(mid + 1, end);
}

void PointCloud::search(Vec3 p, std::uint32_t begin, std::uint32_t end, double& best2) const {
  if (begin >= end) return;
  const std::uint32_t mid = begin + (end - begin) / 2;
  best2 = std::min(best2, distance2(p, points_[mid]));
  if (end - begin == 1) return;
  const int axis = axis_[mid];
  const double delta = coordinate(p, axis) - coordinate(points_[mid], axis);
  const bool lowFirst = delta < 0;
  if (lowFirst) search(p, begin, mid, best2);
  else search(p, mid + 1, end, best2);
  if (delta * delta < best2) {
    if (lowFirst) search(p, mid + 1, end, best2);
    else search(p, begin, mid, best2);
  }
}

double PointCloud::distanceTo(Vec3 p) const {
  if (points_.empty()) return 1e22;
  double best2 = 1e300;
  search(p, 0, static_cast<std::uint32_t>(points_.size()), best2);
  return std::sqrt(best2);
}

}  // namespace geomesh
