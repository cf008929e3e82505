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

PointCloud::PointCloud(std::vector<Vec3> points) {
  std::vector<Entry> entries(points.size());
  for (std::uint32_t k = 0; k < entries.size(); ++k) entries[k] = {points[k], k};
  axis_.assign(entries.size(), 0);
  build(entries, 0, static_cast<std::uint32_t>(entries.size()));
  points_.reserve(entries.size());
  original_.reserve(entries.size());
  for (const Entry& e : entries) {
    points_.push_back(e.point);
    original_.push_back(e.index);
  }
}

// Splits along the axis of largest extent of the range.
void PointCloud::build(std::vector<Entry>& entries, std::uint32_t begin, std::uint32_t end) {
  if (end - begin <= 1) return;
  Vec3 lo = entries[begin].point, hi = lo;
  for (std::uint32_t k = begin; k < end; ++k) {
    const Vec3 q = entries[k].point;
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
  }
  const Vec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(entries.begin() + begin, entries.begin() + mid, entries.begin() + end,
                   [axis](const Entry& a, const Entry& b) {
                     return coordinate(a.point, axis) < coordinate(b.point, axis);
                   });
  axis_[mid] = static_cast<std::uint8_t>(axis);
  build(entries, begin, mid);
  build(entries, mid + 1, end);
}

void PointCloud::search(Vec3 p, std::uint32_t begin, std::uint32_t end, double& best2,
                        std::uint32_t& best) const {
  if (begin >= end) return;
  const std::uint32_t mid = begin + (end - begin) / 2;
  if (const double d2 = distance2(p, points_[mid]); d2 < best2) best2 = d2, best = mid;
  if (end - begin == 1) return;
  const int axis = axis_[mid];
  const double delta = coordinate(p, axis) - coordinate(points_[mid], axis);
  const bool lowFirst = delta < 0;
  if (lowFirst) search(p, begin, mid, best2, best);
  else search(p, mid + 1, end, best2, best);
  if (delta * delta < best2) {
    if (lowFirst) search(p, mid + 1, end, best2, best);
    else search(p, begin, mid, best2, best);
  }
}

double PointCloud::distanceTo(Vec3 p) const {
  if (points_.empty()) return 1e22;
  return nearest(p).distance;
}

PointCloud::Nearest PointCloud::nearest(Vec3 p) const {
  double best2 = 1e300;
  std::uint32_t best = 0;
  search(p, 0, static_cast<std::uint32_t>(points_.size()), best2, best);
  return {original_[best], std::sqrt(best2)};
}

}  // namespace geomesh
