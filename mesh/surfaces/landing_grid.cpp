// LandingGrid: segments and points in a hash grid, queried by the place of an embedded node.
#include "mesh/surfaces/landing_grid.h"

#include <algorithm>
#include <cmath>

namespace geomesh {
namespace {

double distanceToSegment(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double squared = dot(ab, ab);
  const double t = squared > 0 ? std::clamp(dot(p - a, ab) / squared, 0.0, 1.0) : 0.0;
  return distance(p, a + t * ab);
}

}  // namespace

std::size_t LandingGrid::CellHash::operator()(const Cell& c) const {
  std::uint64_t h = 1469598103934665603ull;
  for (std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
  return static_cast<std::size_t>(h);
}

LandingGrid::LandingGrid(const Mesh& mesh, double tolerance, double cell)
    : mesh_(mesh), tolerance_(tolerance), cell_(std::max({cell, 4 * tolerance, 1e-300})) {}

LandingGrid::Cell LandingGrid::cellOf(Vec3 p) const {
  return {static_cast<std::int64_t>(std::floor(p.x / cell_)),
          static_cast<std::int64_t>(std::floor(p.y / cell_)),
          static_cast<std::int64_t>(std::floor(p.z / cell_))};
}

void LandingGrid::insert(std::uint32_t segment, Vec3 lo, Vec3 hi) {
  const Vec3 margin{tolerance_, tolerance_, tolerance_};
  const Cell first = cellOf(lo - margin), last = cellOf(hi + margin);
  for (std::int64_t i = first[0]; i <= last[0]; ++i)
    for (std::int64_t j = first[1]; j <= last[1]; ++j)
      for (std::int64_t k = first[2]; k <= last[2]; ++k) cells_[{i, j, k}].push_back(segment);
}

void LandingGrid::addSegment(NodeIndex a, NodeIndex b, int curve) {
  const Vec3 pa = mesh_.node(a), pb = mesh_.node(b);
  const auto index = static_cast<std::uint32_t>(segments_.size());
  segments_.push_back({a, b, curve});
  insert(index, {std::min(pa.x, pb.x), std::min(pa.y, pb.y), std::min(pa.z, pb.z)},
         {std::max(pa.x, pb.x), std::max(pa.y, pb.y), std::max(pa.z, pb.z)});
}

void LandingGrid::addPoint(NodeIndex n) {
  const auto index = static_cast<std::uint32_t>(segments_.size());
  segments_.push_back({n, n, 0});
  insert(index, mesh_.node(n), mesh_.node(n));
}

LandingGrid::Landing LandingGrid::find(NodeIndex n) const {
  const Vec3 p = mesh_.node(n);
  const auto it = cells_.find(cellOf(p));
  if (it == cells_.end()) return {};
  Landing found;
  for (std::uint32_t s : it->second) {
    const Segment& seg = segments_[s];
    if (seg.a == n || seg.b == n) continue;
    const Vec3 pa = mesh_.node(seg.a), pb = mesh_.node(seg.b);
    if (distanceToSegment(p, pa, pb) > tolerance_) continue;
    if (distance(p, pa) <= tolerance_) found.node = seg.a;
    else if (distance(p, pb) <= tolerance_) found.node = seg.b;
    if (seg.curve != 0) {
      found.curve = seg.curve;
      return found;
    }
  }
  return found;
}

}  // namespace geomesh
