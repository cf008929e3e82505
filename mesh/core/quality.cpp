// Gamma and SICN of triangles and tetrahedra, mesh quality statistics, element measures.
#include "mesh/core/quality.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "mesh/core/element_corners.h"

namespace geomesh {
namespace {

constexpr double kSqrt3 = 1.7320508075688772;

double tetVolume6(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return dot(cross(b - a, c - a), d - a);
}

// Columns of the inverse of the edge matrix of the regular tetrahedron with unit edges
// (vertices (0,0,0), (1,0,0), (1/2,sqrt3/2,0), (1/2,sqrt3/6,sqrt(2/3))).
struct Mat3 {
  Vec3 c0, c1, c2;  // columns
};
Vec3 times(const Mat3& m, Vec3 x) {
  return x.x * m.c0 + x.y * m.c1 + x.z * m.c2;
}
Mat3 times(const Mat3& a, const Mat3& b) {
  return {times(a, b.c0), times(a, b.c1), times(a, b.c2)};
}

Mat3 inverse(const Mat3& m) {
  const Vec3 r0 = cross(m.c1, m.c2), r1 = cross(m.c2, m.c0), r2 = cross(m.c0, m.c1);
  const double det = dot(m.c0, r0);
  // Rows of the inverse are r0, r1, r2 over det; convert to columns.
  return {Vec3{r0.x, r1.x, r2.x} / det, Vec3{r0.y, r1.y, r2.y} / det, Vec3{r0.z, r1.z, r2.z} / det};
}

Mat3 regularTetInverse() {
  const Mat3 w{{1, 0, 0}, {0.5, kSqrt3 / 2, 0}, {0.5, kSqrt3 / 6, std::sqrt(2.0 / 3.0)}};
  return inverse(w);
}

double frobenius2(const Mat3& m) {
  return dot(m.c0, m.c0) + dot(m.c1, m.c1) + dot(m.c2, m.c2);
}

}  // namespace

double triangleGamma(Vec3 a, Vec3 b, Vec3 c) {
  const double la = distance(b, c), lb = distance(c, a), lc = distance(a, b);
  const double area = 0.5 * norm(cross(b - a, c - a));
  const double product = la * lb * lc * (la + lb + lc);
  return product > 0 ? 16 * area * area / product : 0;
}

double triangleSicn(Vec3 a, Vec3 b, Vec3 c, Vec3 normal) {
  const Vec3 n = cross(b - a, c - a);
  const double squares = dot(b - a, b - a) + dot(c - b, c - b) + dot(a - c, a - c);
  if (!(squares > 0)) return 0;
  const double q = 2 * kSqrt3 * norm(n) / squares;
  return dot(normal, normal) > 0 && dot(n, normal) < 0 ? -q : q;
}

double tetGamma(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double volume = std::abs(tetVolume6(a, b, c, d)) / 6;
  const double faces = 0.5 * (norm(cross(b - a, c - a)) + norm(cross(b - a, d - a)) +
                              norm(cross(c - a, d - a)) + norm(cross(c - b, d - b)));
  if (!(volume > 0) || !(faces > 0)) return 0;
  const double inradius = 3 * volume / faces;
  const Vec3 u = b - a, v = c - a, w = d - a;
  const Vec3 center =
      (dot(u, u) * cross(v, w) + dot(v, v) * cross(w, u) + dot(w, w) * cross(u, v)) /
      (2 * dot(u, cross(v, w)));
  return 3 * inradius / norm(center);
}

double tetSicn(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Mat3 j{b - a, c - a, d - a};
  const double det = dot(j.c0, cross(j.c1, j.c2));
  if (det == 0) return 0;
  const Mat3 m = times(j, regularTetInverse());
  const double kappa = std::sqrt(frobenius2(m) * frobenius2(inverse(m))) / 3;
  return det > 0 ? 1 / kappa : -1 / kappa;
}

double elementQuality(ElementType type, std::span<const Vec3> corners, QualityMeasure measure) {
  const bool gamma = measure == QualityMeasure::Gamma;
  const auto& v = corners;
  switch (family(type)) {
    case ElementFamily::Triangle:
      return gamma ? triangleGamma(v[0], v[1], v[2]) : triangleSicn(v[0], v[1], v[2]);
    case ElementFamily::Tet:
      return gamma ? tetGamma(v[0], v[1], v[2], v[3]) : tetSicn(v[0], v[1], v[2], v[3]);
    default:
      return cornerScaledJacobian(type, corners);
  }
}

QualityStats meshQuality(const Mesh& mesh, int dim, QualityMeasure measure) {
  QualityStats stats;
  double sum = 0, lowest = 1e300;
  const ElementFamily wanted = dim == 2 ? ElementFamily::Triangle : ElementFamily::Tet;
  const int corners = dim == 2 ? 3 : 4;
  for (const auto& [id, em] : mesh.entities()) {
    for (const ElementBlock& block : em.blocks) {
      if (family(block.type) != wanted) continue;
      // Elements of any order, measured on their corners (their first nodes).
      for (std::size_t e = 0; e < block.size(); ++e) {
        const auto n = block.element(e);
        std::array<Vec3, 4> v;
        for (int c = 0; c < corners; ++c) v[c] = mesh.node(n[c]);
        const double q = elementQuality(block.type, std::span<const Vec3>(v.data(), corners),
                                        measure);
        sum += q;
        lowest = std::min(lowest, q);
        ++stats.count;
      }
    }
  }
  if (stats.count > 0) stats.min = lowest, stats.mean = sum / static_cast<double>(stats.count);
  return stats;
}

namespace {

// Three tetrahedra of the prism a, b, c (bottom), d, e, f (top): exact when its sides are flat.
double prismVolume(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e, Vec3 f) {
  return (std::abs(tetVolume6(a, b, c, f)) + std::abs(tetVolume6(a, b, f, e)) +
          std::abs(tetVolume6(a, e, f, d))) /
         6;
}

}  // namespace

double elementMeasure(const Mesh& mesh, ElementType type, std::span<const NodeIndex> nodes) {
  auto p = [&](int i) { return mesh.node(nodes[i]); };
  auto triangleArea = [](Vec3 a, Vec3 b, Vec3 c) { return 0.5 * norm(cross(b - a, c - a)); };
  switch (family(type)) {
    case ElementFamily::Line: return distance(p(0), p(1));
    case ElementFamily::Triangle: return triangleArea(p(0), p(1), p(2));
    case ElementFamily::Quad:
      return triangleArea(p(0), p(1), p(2)) + triangleArea(p(0), p(2), p(3));
    case ElementFamily::Tet: return std::abs(tetVolume6(p(0), p(1), p(2), p(3))) / 6;
    case ElementFamily::Prism: return prismVolume(p(0), p(1), p(2), p(3), p(4), p(5));
    case ElementFamily::Pyramid:
      return (std::abs(tetVolume6(p(0), p(1), p(2), p(4))) +
              std::abs(tetVolume6(p(0), p(2), p(3), p(4)))) /
             6;
    case ElementFamily::Hex:
      return prismVolume(p(0), p(1), p(2), p(4), p(5), p(6)) +
             prismVolume(p(0), p(2), p(3), p(4), p(6), p(7));
    default: return 0;
  }
}

namespace {

// The unit vector from a to b (zero when they coincide).
Vec3 unitEdge(Vec3 a, Vec3 b) {
  const double l = distance(a, b);
  return l > 0 ? (b - a) / l : Vec3{};
}

double tripleAt(std::span<const Vec3> v, const std::array<int, 4>& c) {
  return dot(unitEdge(v[c[0]], v[c[1]]),
             cross(unitEdge(v[c[0]], v[c[2]]), unitEdge(v[c[0]], v[c[3]])));
}

// The smallest scaled cross product at the corners of a polygon, along its mean normal.
double polygonCorners(std::span<const Vec3> v, double ideal) {
  const std::size_t n = v.size();
  Vec3 normal{};
  for (std::size_t k = 0; k < n; ++k) normal = normal + cross(v[k], v[(k + 1) % n]);
  const double length = norm(normal);
  if (!(length > 0)) return 0;
  normal = normal / length;
  double worst = 1;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 a = unitEdge(v[k], v[(k + 1) % n]), b = unitEdge(v[k], v[(k + n - 1) % n]);
    worst = std::min(worst, dot(cross(a, b), normal) / ideal);
  }
  return worst;
}

}  // namespace

double cornerScaledJacobian(ElementType type, std::span<const Vec3> nodes) {
  const ElementFamily f = family(type);
  const std::span<const Vec3> v = nodes.first(std::min<std::size_t>(nodes.size(), vertexCount(f)));
  const double sin60 = std::sqrt(3.0) / 2;
  switch (f) {
    case ElementFamily::Triangle: return std::min(1.0, polygonCorners(v, sin60));
    case ElementFamily::Quad: return std::min(1.0, polygonCorners(v, 1));
    case ElementFamily::Pyramid: {
      // At each base corner: the two base edges and the edge to the apex (equilateral
      // faces: sin 45 degrees).
      double worst = 1;
      for (std::size_t k = 0; k < 4; ++k) {
        const Vec3 corner[4] = {v[k], v[(k + 1) % 4], v[(k + 3) % 4], v[4]};
        worst = std::min(worst, tripleAt(corner, {0, 1, 2, 3}) / (std::sqrt(2.0) / 2));
      }
      return std::min(1.0, worst);
    }
    case ElementFamily::Tet:
    case ElementFamily::Prism:
    case ElementFamily::Hex: {
      const double ideal = f == ElementFamily::Tet ? 1 / std::sqrt(2.0)
                           : f == ElementFamily::Prism     ? sin60
                                                           : 1;
      const ElementType linear = linearType(f);
      double worst = 1;
      for (const std::array<int, 4>& corner : cornerNeighbours(linear))
        worst = std::min(worst, tripleAt(v, corner) / ideal);
      return std::min(1.0, worst);
    }
    default: return 1;
  }
}

}  // namespace geomesh
