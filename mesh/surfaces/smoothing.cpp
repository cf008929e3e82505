// Laplacian smoothing of a 2D triangulation with quality guards, then metric Lawson flips.
#include "mesh/surfaces/smoothing.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "mesh/core/predicates.h"

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

// gamma of a triangle in the metric at its centroid (plain lengths without one); 0 if it is
// not positive.
double quality(Vec2 a, Vec2 b, Vec2 c, const SurfaceMetric* metric) {
  if (metric) {
    const MetricFrame f(metric->at({(a.u + b.u + c.u) / 3, (a.v + b.v + c.v) / 3}));
    a = f.apply(a), b = f.apply(b), c = f.apply(c);
  }
  const double area = 0.5 * ((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
  if (!(area > 0)) return 0;
  const auto length = [](Vec2 d) { return std::sqrt(d.u * d.u + d.v * d.v); };
  const double la = length({c.u - b.u, c.v - b.v}), lb = length({a.u - c.u, a.v - c.v}),
               lc = length({b.u - a.u, b.v - a.v});
  return 16 * area * area / (la * lb * lc * (la + lb + lc));
}

// The worst quality of v's triangles with v at p (plain lengths without a metric, -1 if one
// of them is not positive); without `withQuality`, 1 if all are positive.
double worstAround(const Triangulation2D& tri, const Incidence& inc, std::uint32_t v, Vec2 p,
                   bool withQuality, const SurfaceMetric* metric) {
  double worst = 1;
  for (std::uint32_t k = inc.offsets[v]; k < inc.offsets[v + 1]; ++k) {
    const std::uint32_t t = inc.triangles[k];
    Vec2 q[3];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t w = tri.vertex(3 * t + i);
      q[i] = w == v ? p : tri.point(w);
    }
    if (orient2d(q[0], q[1], q[2]) <= 0) return -1;
    if (withQuality) worst = std::min(worst, quality(q[0], q[1], q[2], metric));
  }
  return worst;
}

// Moves v to the centroid of its ring if every triangle around it stays positive (and, with
// the quality guard, the worst of them is no worse; else half or a quarter of the way).
void smoothVertex(Triangulation2D& tri, const Incidence& inc, std::uint32_t v,
                  const SurfaceMetric* metric, SmoothingGuard guard) {
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
  if (guard == SmoothingGuard::Validity) {
    if (worstAround(tri, inc, v, target, false, nullptr) > 0) tri.movePoint(v, target);
    return;
  }
  const double before = worstAround(tri, inc, v, old, true, metric);
  for (double step : {1.0, 0.5, 0.25}) {
    const Vec2 p{old.u + step * (target.u - old.u), old.v + step * (target.v - old.v)};
    if (worstAround(tri, inc, v, p, true, metric) >= before) {
      tri.movePoint(v, p);
      return;
    }
  }
}

// True if the free edge of `corner` is not locally Delaunay in the metric at its midpoint.
bool shouldFlipInMetric(const Triangulation2D& tri, std::uint32_t corner,
                        const SurfaceMetric& metric) {
  const std::uint32_t across = tri.neighbour(corner);
  if (across == kNone || tri.kind(corner) != EdgeKind::Free) return false;
  const std::uint32_t t = corner / 3;
  const Vec2 a = tri.point(tri.vertex(3 * t)), b = tri.point(tri.vertex(3 * t + 1)),
             c = tri.point(tri.vertex(3 * t + 2)), d = tri.point(tri.vertex(across));
  const Vec2 u = tri.point(tri.vertex(Triangulation2D::nextCorner(corner)));
  const Vec2 w = tri.point(tri.vertex(Triangulation2D::prevCorner(corner)));
  const MetricFrame f(metric.at({0.5 * (u.u + w.u), 0.5 * (u.v + w.v)}));
  // The flip must also keep both new triangles positive in the plane.
  const Vec2 x = tri.point(tri.vertex(corner));
  if (orient2d(x, u, d) <= 0 || orient2d(d, w, x) <= 0) return false;
  return incircle(f.apply(a), f.apply(b), f.apply(c), f.apply(d)) > 0;
}

// Lawson flips in a metric that varies from edge to edge: no global Delaunay triangulation
// exists to converge to, so the number of flips is bounded.
void restoreMetricDelaunay(Triangulation2D& tri, std::vector<std::uint32_t> stack,
                           const SurfaceMetric& metric) {
  const std::size_t budget = 4 * stack.size();
  tri.flipWhile(
      std::move(stack),
      [&](std::uint32_t c) { return shouldFlipInMetric(tri, c, metric); }, budget);
}

}  // namespace

void smoothTriangulation(Triangulation2D& tri, const std::vector<std::uint8_t>& inside,
                         std::uint32_t firstMovable, int passes, const SurfaceMetric* metric,
                         SmoothingGuard guard) {
  const std::uint32_t vertexCount = static_cast<std::uint32_t>(tri.pointCount());
  for (int pass = 0; pass < passes; ++pass) {
    const Incidence inc = buildIncidence(tri, inside);
    for (std::uint32_t v = firstMovable; v < vertexCount; ++v)
      smoothVertex(tri, inc, v, metric, guard);
    std::vector<std::uint32_t> corners;
    corners.reserve(3 * tri.triangleCount());
    for (std::uint32_t t = 0; t < tri.triangleCount(); ++t)
      if (inside[t]) corners.insert(corners.end(), {3 * t, 3 * t + 1, 3 * t + 2});
    if (metric)
      restoreMetricDelaunay(tri, std::move(corners), *metric);
    else
      tri.restoreDelaunay(std::move(corners));
  }
}

}  // namespace geomesh
