#include "mesh/smoothing.h"

#include <numeric>

#include "mesh/predicates.h"

namespace geomesh {
namespace {

// Vertex-to-triangle incidence in compressed rows: triangles of v are
// triangles[offsets[v] .. offsets[v + 1]).
struct Incidence {
  std::vector<std::uint32_t> offsets, triangles;
};

Incidence buildIncidence(const Triangulation2D& tri, const std::vector<std::uint8_t>& inside) {
  Incidence inc;
  inc.offsets.assign(tri.pointCount() + 1, 0);
  const std::uint32_t n = static_cast<std::uint32_t>(tri.triangleCount());
  for (std::uint32_t t = 0; t < n; ++t)
    if (inside[t])
      for (int i = 0; i < 3; ++i) ++inc.offsets[tri.vertex(3 * t + i) + 1];
  std::partial_sum(inc.offsets.begin(), inc.offsets.end(), inc.offsets.begin());
  inc.triangles.resize(inc.offsets.back());
  std::vector<std::uint32_t> fill(inc.offsets.begin(), inc.offsets.end() - 1);
  for (std::uint32_t t = 0; t < n; ++t)
    if (inside[t])
      for (int i = 0; i < 3; ++i) inc.triangles[fill[tri.vertex(3 * t + i)]++] = t;
  return inc;
}

// Moves v to the centroid of its ring if every triangle around it stays positive.
void smoothVertex(Triangulation2D& tri, const Incidence& inc, std::uint32_t v) {
  const std::uint32_t begin = inc.offsets[v], end = inc.offsets[v + 1];
  if (begin == end) return;
  double su = 0, sv = 0;
  for (std::uint32_t k = begin; k < end; ++k) {
    const std::uint32_t t = inc.triangles[k];
    for (int i = 0; i < 3; ++i) {
      const Vec2 q = tri.point(tri.vertex(3 * t + i));
      su += q.u;
      sv += q.v;
    }
  }
  // Each ring vertex appears in two triangles, v itself in all of them.
  const Vec2 old = tri.point(v);
  const double count = 2.0 * (end - begin);
  const Vec2 target{(su - (end - begin) * old.u) / count, (sv - (end - begin) * old.v) / count};
  for (std::uint32_t k = begin; k < end; ++k) {
    const std::uint32_t t = inc.triangles[k];
    Vec2 q[3];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t w = tri.vertex(3 * t + i);
      q[i] = w == v ? target : tri.point(w);
    }
    if (orient2d(q[0], q[1], q[2]) <= 0) return;
  }
  tri.movePoint(v, target);
}

}  // namespace

void smoothTriangulation(Triangulation2D& tri, const std::vector<std::uint8_t>& inside,
                         std::uint32_t firstMovable, int passes) {
  const std::uint32_t vertexCount = static_cast<std::uint32_t>(tri.pointCount());
  for (int pass = 0; pass < passes; ++pass) {
    const Incidence inc = buildIncidence(tri, inside);
    for (std::uint32_t v = firstMovable; v < vertexCount; ++v) smoothVertex(tri, inc, v);
    std::vector<std::uint32_t> corners;
    corners.reserve(3 * tri.triangleCount());
    for (std::uint32_t t = 0; t < tri.triangleCount(); ++t)
      if (inside[t]) corners.insert(corners.end(), {3 * t, 3 * t + 1, 3 * t + 2});
    tri.restoreDelaunay(std::move(corners));
  }
}

}  // namespace geomesh
