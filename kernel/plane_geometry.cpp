// fitPlane by Newell's method, and PlaneGeometry's axes and projection.
#include "kernel/plane_geometry.h"

#include <algorithm>
#include <cmath>

namespace geomesh {

PlaneFit fitPlane(std::span<const Vec3> polygon) {
  PlaneFit fit;
  if (polygon.empty()) return fit;
  for (Vec3 p : polygon) fit.origin += p;
  fit.origin = fit.origin / static_cast<double>(polygon.size());
  // Newell's method: the sum of the cross products of consecutive points (taken relative to
  // the centroid, which keeps the sum accurate far from the origin) is twice the vector area.
  Vec3 area;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 a = polygon[i] - fit.origin;
    const Vec3 b = polygon[(i + 1) % polygon.size()] - fit.origin;
    area += cross(a, b);
  }
  fit.normal = normalized(area);
  if (norm(area) == 0) return fit;
  for (Vec3 p : polygon)
    fit.maxDeviation = std::max(fit.maxDeviation, std::abs(dot(p - fit.origin, fit.normal)));
  return fit;
}

namespace {

Vec3 leastAlignedAxis(Vec3 n) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  if (ax <= ay && ax <= az) return {1, 0, 0};
  if (ay <= az) return {0, 1, 0};
  return {0, 0, 1};
}

}  // namespace

PlaneGeometry::PlaneGeometry(Vec3 origin, Vec3 normal) : origin_(origin) {
  const Vec3 n = normalized(normal);
  const Vec3 axis = leastAlignedAxis(n);
  uAxis_ = normalized(axis - dot(axis, n) * n);
  vAxis_ = cross(n, uAxis_);
}

void PlaneGeometry::include(Vec3 p) {
  const Vec2 uv = project(p);
  bounds_.u = {std::min(bounds_.u.min, uv.u), std::max(bounds_.u.max, uv.u)};
  bounds_.v = {std::min(bounds_.v.min, uv.v), std::max(bounds_.v.max, uv.v)};
}

Vec2 PlaneGeometry::project(Vec3 p) const {
  const Vec3 d = p - origin_;
  return {dot(d, uAxis_), dot(d, vAxis_)};
}

}  // namespace geomesh
