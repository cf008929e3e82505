// AffineMap's translation, rotation, symmetry and dilation, rounded as Gmsh's built-in kernel.
#include "kernel/affine_map.h"

#include <cmath>
#include <vector>
#include <utility>
#include <optional>
#include <algorithm>

#include "kernel/geometry_error.h"

namespace geomesh {

AffineMap AffineMap::translation(Vec3 d) {
  return {{1, 0, 0, d.x, 0, 1, 0, d.y, 0, 0, 1, d.z}};
}

AffineMap AffineMap::rotation(Vec3 axis, Vec3 point, double angle) {
  if (norm(axis) == 0) throw GeometryError("Rotation: the axis is the zero vector");
  const Vec3 u = normalized(axis);
  const double c = std::cos(angle), s = std::sin(angle);
  // The rotation matrix of angle `angle` about the unit vector u, term by term.
  AffineMap map;
  const double t = 1 - c;
  map.m = {u.x * u.x * t + c,       u.x * u.y * t - u.z * s, u.x * u.z * t + u.y * s, 0,
           u.x * u.y * t + u.z * s, u.y * u.y * t + c,       u.y * u.z * t - u.x * s, 0,
           u.x * u.z * t - u.y * s, u.y * u.z * t + u.x * s, u.z * u.z * t + c,       0};
  map.pivot = point;
  return map;
}

// The Householder reflection, written as the built-in kernel of Gmsh writes it (so that it
// rounds the same): I + f n n^T and f d n, with f = -2 / |n|^2.
AffineMap AffineMap::symmetry(double a, double b, double c, double d) {
  const double n2 = a * a + b * b + c * c;
  if (n2 == 0) throw GeometryError("Symmetry: the plane's normal is the zero vector");
  const double f = -2.0 / n2;
  const double n[3] = {a, b, c};
  AffineMap map;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) map.m[4 * i + j] = (i == j ? 1.0 : 0.0) + n[i] * n[j] * f;
    map.m[4 * i + 3] = n[i] * d * f;
  }
  return map;
}

AffineMap AffineMap::dilation(Vec3 center, Vec3 factors) {
  return {{factors.x, 0, 0, center.x * (1 - factors.x), 0, factors.y, 0,
           center.y * (1 - factors.y), 0, 0, factors.z, center.z * (1 - factors.z)}};
}

std::array<double, 16> AffineMap::homogeneous() const {
  std::array<double, 16> h{};
  const double p[3] = {pivot.x, pivot.y, pivot.z};
  for (std::size_t i = 0; i < 3; ++i) {
    double moved = 0;
    for (std::size_t j = 0; j < 3; ++j) {
      h[4 * i + j] = m[4 * i + j];
      moved += m[4 * i + j] * p[j];
    }
    h[4 * i + 3] = m[4 * i + 3] + p[i] - moved;
  }
  h[15] = 1;
  return h;
}

namespace {

// An orthonormal frame from three points that are not collinear: the first axis along b - a,
// the second in the plane of the three.
std::array<Vec3, 3> frameOf(Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 e1 = (b - a) / norm(b - a);
  const Vec3 side = (c - a) - dot(c - a, e1) * e1;
  const Vec3 e2 = side / norm(side);
  return {e1, e2, cross(e1, e2)};
}

}  // namespace

std::optional<AffineMap> rigidMotion(const std::vector<std::pair<Vec3, Vec3>>& pairs,
                                     double tolerance) {
  if (pairs.empty()) return std::nullopt;
  const Vec3 shift = pairs[0].second - pairs[0].first;
  AffineMap map = AffineMap::translation(shift);
  auto fits = [&] {
    return std::all_of(pairs.begin(), pairs.end(), [&](const auto& p) {
      return distance(map.apply(p.first), p.second) <= tolerance;
    });
  };
  if (fits()) return map;
  const Vec3 a = pairs[0].first;
  std::size_t far = 0, wide = 0;
  for (std::size_t k = 1; k < pairs.size(); ++k)
    if (distance(pairs[k].first, a) > distance(pairs[far].first, a)) far = k;
  const Vec3 axis = pairs[far].first - a;
  auto offAxis = [&](std::size_t k) { return norm(cross(pairs[k].first - a, axis)); };
  for (std::size_t k = 1; k < pairs.size(); ++k)
    if (offAxis(k) > offAxis(wide)) wide = k;
  if (!(offAxis(wide) > tolerance * norm(axis))) return std::nullopt;
  const auto from = frameOf(a, pairs[far].first, pairs[wide].first);
  const auto to = frameOf(pairs[0].second, pairs[far].second, pairs[wide].second);
  // Rotation R = sum over axes of to[i] from[i]^T; translation takes a onto its image.
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (int i = 0; i < 3; ++i) {
        const double t[3] = {to[i].x, to[i].y, to[i].z}, f[3] = {from[i].x, from[i].y, from[i].z};
        sum += t[r] * f[c];
      }
      map.m[static_cast<std::size_t>(4 * r + c)] = sum;
    }
  map.m[3] = map.m[7] = map.m[11] = 0;
  const Vec3 moved = map.apply(a);
  map.m[3] = pairs[0].second.x - moved.x;
  map.m[7] = pairs[0].second.y - moved.y;
  map.m[11] = pairs[0].second.z - moved.z;
  if (!fits()) return std::nullopt;
  return map;
}

}  // namespace geomesh
