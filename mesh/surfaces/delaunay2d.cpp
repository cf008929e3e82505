// Triangulation2D: visibility-walk location, Bowyer-Watson insertion, flips, metric in-circle.
#include "mesh/surfaces/delaunay2d.h"

#include <algorithm>
#include <cmath>

#include "mesh/core/predicates.h"
#include "mesh/core/spatial_sort.h"

namespace geomesh {

std::uint32_t Triangulation2D::nextRandom() {
  random_ ^= random_ << 13;
  random_ ^= random_ >> 17;
  random_ ^= random_ << 5;
  return random_;
}

// Visibility walk; the first edge tried is chosen at random so that the walk cannot cycle in
// a triangulation that is not Delaunay (after edge recovery).
std::uint32_t Triangulation2D::locate(Vec2 p, std::uint32_t start) {
  std::uint32_t t = start;
  std::uint32_t cameFrom = kNone;
  for (;;) {
    const std::uint32_t first = nextRandom() % 3;
    bool moved = false;
    for (std::uint32_t k = 0; k < 3 && !moved; ++k) {
      const std::uint32_t c = 3 * t + (first + k) % 3;
      if (c == cameFrom) continue;
      const Vec2 a = points_[vertex_[nextCorner(c)]];
      const Vec2 b = points_[vertex_[prevCorner(c)]];
      if (orient2d(a, b, p) < 0) {
        if (neighbour_[c] == kNone) return kNone;
        cameFrom = neighbour_[c];
        t = cameFrom / 3;
        moved = true;
      }
    }
    if (!moved) return t;
  }
}

bool Triangulation2D::inCircumcircle(std::uint32_t t, Vec2 p, const MetricFrame* metric) const {
  const std::uint32_t* w = &vertex_[3 * t];
  if (!metric) return incircle(points_[w[0]], points_[w[1]], points_[w[2]], p) > 0;
  return incircle(metric->apply(points_[w[0]]), metric->apply(points_[w[1]]),
                  metric->apply(points_[w[2]]), metric->apply(p)) > 0;
}

bool Triangulation2D::growCavity(std::uint32_t v, std::uint32_t containing,
                                 const MetricFrame* metric) {
  ++epoch_;
  const std::uint32_t inside = 2 * epoch_, outside = 2 * epoch_ + 1;
  const Vec2 p = points_[v];
  cavity_.clear();
  rimEdges_.clear();
  cavity_.push_back(containing);
  mark_[containing] = inside;
  for (std::size_t next = 0; next < cavity_.size(); ++next) {
    const std::uint32_t t = cavity_[next];
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
      const std::uint32_t across = neighbour_[c];
      if (across != kNone && kind_[c] == EdgeKind::Free) {
        const std::uint32_t n = across / 3;
        if (mark_[n] == inside) continue;
        if (mark_[n] != outside) {
          if (inCircumcircle(n, p, metric)) {
            mark_[n] = inside;
            cavity_.push_back(n);
            continue;
          }
          mark_[n] = outside;
        }
      }
      rimEdges_.push_back({vertex_[nextCorner(c)], vertex_[prevCorner(c)], across, kind_[c]});
    }
  }
  for (const CavityEdge& e : rimEdges_)
    if (orient2d(points_[e.a], points_[e.b], p) <= 0) return false;
  return true;
}

Triangulation2D::InsertStatus Triangulation2D::insert(std::uint32_t v, std::uint32_t containing) {
  const InsertStatus status = findCavity(v, containing);
  if (status == InsertStatus::Inserted) commitCavity(v);
  return status;
}

Triangulation2D::InsertStatus Triangulation2D::findCavity(std::uint32_t v, std::uint32_t containing,
                                                          const MetricFrame* metric) {
  const Vec2 p = points_[v];
  for (std::uint32_t c = 3 * containing; c < 3 * containing + 3; ++c)
    if (points_[vertex_[c]] == p) return InsertStatus::Duplicate;
  if (!growCavity(v, containing, metric)) return InsertStatus::Rejected;
  return InsertStatus::Inserted;
}

void Triangulation2D::commitCavity(std::uint32_t v) {
  created_.clear();
  rim_.clear();
  const std::size_t count = rimEdges_.size();
  for (std::size_t j = 0; j < count; ++j) {
    const std::uint32_t t = j < cavity_.size() ? cavity_[j] : newTriangle();
    const CavityEdge& e = rimEdges_[j];
    setTriangle(t, e.a, e.b, v);
    link(3 * t + 2, e.outside, e.kind);
    created_.push_back(t);
    rim_.push_back(e.outside);
  }
  // Around v the new triangles form a fan: the one starting at vertex b follows the one
  // ending at b.
  auto& byStart = fanIndex_;
  byStart.clear();
  for (std::size_t j = 0; j < count; ++j) byStart.emplace_back(rimEdges_[j].a, created_[j]);
  std::sort(byStart.begin(), byStart.end());
  for (std::size_t j = 0; j < count; ++j) {
    const std::uint32_t b = rimEdges_[j].b;
    const auto it = std::lower_bound(byStart.begin(), byStart.end(), std::pair{b, 0u});
    link(3 * created_[j], 3 * it->second + 1, EdgeKind::Free);
  }
}

bool Triangulation2D::shouldFlip(std::uint32_t c) const {
  const std::uint32_t across = neighbour_[c];
  if (across == kNone || kind_[c] != EdgeKind::Free) return false;
  const std::uint32_t t = c / 3;
  return incircle(points_[vertex_[3 * t]], points_[vertex_[3 * t + 1]], points_[vertex_[3 * t + 2]],
                  points_[vertex_[across]]) > 0;
}

void Triangulation2D::restoreDelaunay(std::vector<std::uint32_t> stack) {
  flipWhile(std::move(stack), [this](std::uint32_t c) { return shouldFlip(c); });
}

Triangulation2D delaunayTriangulation(std::span<const Vec2> points) {
  Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (Vec2 p : points) {
    lo = {std::min(lo.u, p.u), std::min(lo.v, p.v)};
    hi = {std::max(hi.u, p.u), std::max(hi.v, p.v)};
  }
  if (points.empty()) lo = hi = {0, 0};
  Triangulation2D tri(lo, hi);
  for (Vec2 p : points) tri.addPoint(p);
  std::uint32_t hint = 0;
  for (std::uint32_t k : spatialOrder(points)) {
    const std::uint32_t v = k + Triangulation2D::kFirstVertex;
    const std::uint32_t t = tri.locate(tri.point(v), hint);
    if (tri.insert(v, t) == Triangulation2D::InsertStatus::Inserted) hint = tri.created()[0];
  }
  return tri;
}

}  // namespace geomesh
