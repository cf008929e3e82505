// gradeMetrics: Dijkstra-like propagation of metric size bounds along the edges of a mesh.
#include "mesh/surfaces/anisotropic_gradation.h"

#include <cmath>
#include <queue>
#include <utility>
#include <vector>

#include "mesh/surfaces/anisotropic_metric.h"

namespace geomesh {
namespace {

// A vertex is lowered again only when its metric's squared lengths grow by this much.
constexpr double kTolerance = 0.01;
// Each vertex is settled at most this many times (a bound the tolerance makes unreachable in
// practice, kept so that rounding can never loop).
constexpr std::size_t kVisitsPerVertex = 16;

}  // namespace

void gradeMetrics(std::span<const Vec2> points, VertexGraph graph, std::span<Metric2> metrics,
                  double ratio) {
  if (!(ratio > 1) || !std::isfinite(ratio)) return;
  const double rate = ratio - 1;
  const std::size_t n = metrics.size();
  // Largest eigenvalue first: the smallest sizes bound their neighbours, not the reverse.
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry> queue;
  std::vector<double> key(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (graph.offsets[v] == graph.offsets[v + 1]) continue;
    key[v] = eigen(metrics[v]).large;
    queue.push({key[v], v});
  }
  std::size_t budget = kVisitsPerVertex * n;
  while (!queue.empty() && budget > 0) {
    const auto [k, v] = queue.top();
    queue.pop();
    if (k != key[v]) continue;  // lowered since: a newer entry stands for it
    --budget;
    const Vec2 p = points[v];
    for (std::uint32_t i = graph.offsets[v]; i < graph.offsets[v + 1]; ++i) {
      const std::uint32_t w = graph.neighbours[i];
      const Vec2 d{points[w].u - p.u, points[w].v - p.v};
      if (!intersectInto(metrics[w], grownAlong(metrics[v], d, rate), kTolerance)) continue;
      key[w] = eigen(metrics[w]).large;
      queue.push({key[w], w});
    }
  }
}

}  // namespace geomesh
