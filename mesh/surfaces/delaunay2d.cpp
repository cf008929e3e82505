#include "mesh/surfaces/delaunay2d.h"

#include <algorithm>
#include <cmath>

#include "mesh/core/predicates.h"
#include "mesh/core/spatial_sort.h"

namespace geomesh {
namespace {

constexpr std::uint32_t kNext[3] = {1, 2, 0};
constexpr std::uint32_t kPrev[3] = {2, 0, 1};

std::uint32_t triangleOfCorner(std::uint32_t c) {
  return c / 3;
}
std::uint32_t nextCorner(std::uint32_t c) {
  return c - c % 3 + kNext[c % 3];
}
std::uint32_t prevCorner(std::uint32_t c) {
  return c - c % 3 + kPrev[c % 3];
}

}  // namespace

Triangulation2D::Triangulation2D(Vec2 boxMin, Vec2 boxMax) {
  const Vec2 center{0.5 * (boxMin.u + boxMax.u), 0.5 * (boxMin.v + boxMax.v)};
  double extent = std::max(boxMax.u - boxMin.u, boxMax.v - boxMin.v);
  if (!(extent > 0)) extent = 1;
  // A triangle whose inscribed circle has radius 10x the box: far enough that the enclosing
  // vertices never get close to the domain, near enough to keep the predicates' fast path.
  const double radius = 20 * extent;
  constexpr double kPi = 3.14159265358979323846;
  for (int k = 0; k < 3; ++k) {
    const double angle = kPi / 2 + k * 2 * kPi / 3;
    addPoint({center.u + radius * std::cos(angle), center.v + radius * std::sin(angle)});
  }
  vertex_ = {0, 1, 2};
  neighbour_ = {kNone, kNone, kNone};
  kind_.assign(3, EdgeKind::Free);
  mark_.assign(1, 0);
  vertexTriangle_ = {0, 0, 0};
}

std::uint32_t Triangulation2D::addPoint(Vec2 p) {
  points_.push_back(p);
  vertexTriangle_.push_back(kNone);
  return static_cast<std::uint32_t>(points_.size() - 1);
}

void Triangulation2D::removeLastPoint() {
  if (points_.empty() || vertexTriangle_.back() != kNone) return;
  points_.pop_back();
  vertexTriangle_.pop_back();
}

std::uint32_t Triangulation2D::nextRandom() {
  random_ ^= random_ << 13;
  random_ ^= random_ >> 17;
  random_ ^= random_ << 5;
  return random_;
}

void Triangulation2D::setKind(std::uint32_t corner, EdgeKind k) {
  kind_[corner] = k;
  if (neighbour_[corner] != kNone) kind_[neighbour_[corner]] = k;
}

void Triangulation2D::setTriangle(std::uint32_t t, std::uint32_t a, std::uint32_t b,
                                  std::uint32_t c) {
  vertex_[3 * t] = a;
  vertex_[3 * t + 1] = b;
  vertex_[3 * t + 2] = c;
  vertexTriangle_[a] = vertexTriangle_[b] = vertexTriangle_[c] = t;
}

void Triangulation2D::link(std::uint32_t c1, std::uint32_t c2, EdgeKind k) {
  neighbour_[c1] = c2;
  kind_[c1] = k;
  if (c2 != kNone) {
    neighbour_[c2] = c1;
    kind_[c2] = k;
  }
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
        t = triangleOfCorner(cameFrom);
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
        const std::uint32_t n = triangleOfCorner(across);
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
    std::uint32_t t;
    if (j < cavity_.size()) {
      t = cavity_[j];
    } else {
      t = static_cast<std::uint32_t>(triangleCount());
      vertex_.resize(vertex_.size() + 3);
      neighbour_.resize(neighbour_.size() + 3);
      kind_.resize(kind_.size() + 3);
      mark_.push_back(0);
    }
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

std::uint32_t Triangulation2D::findEdge(std::uint32_t a, std::uint32_t b) const {
  const std::uint32_t start = vertexTriangle_[a];
  if (start == kNone) return kNone;
  // Turn around a one way, then, if the hull stops us, the other way.
  for (int direction = 0; direction < 2; ++direction) {
    std::uint32_t t = start;
    bool hitHull = false;
    do {
      std::uint32_t i = 0;
      while (vertex_[3 * t + i] != a) ++i;
      if (vertex_[3 * t + kNext[i]] == b) return 3 * t + kPrev[i];
      const std::uint32_t across =
          direction == 0 ? neighbour_[3 * t + kPrev[i]] : neighbour_[3 * t + kNext[i]];
      if (across == kNone) {
        hitHull = true;
        break;
      }
      t = triangleOfCorner(across);
    } while (t != start);
    if (!hitHull) return kNone;
  }
  return kNone;
}

void Triangulation2D::flip(std::uint32_t c) {
  const std::uint32_t t = triangleOfCorner(c);
  const std::uint32_t c2 = neighbour_[c];
  const std::uint32_t t2 = triangleOfCorner(c2);
  const std::uint32_t x = vertex_[c], u = vertex_[nextCorner(c)], w = vertex_[prevCorner(c)];
  const std::uint32_t y = vertex_[c2];
  const std::uint32_t n1 = neighbour_[prevCorner(c)], n2 = neighbour_[nextCorner(c)];
  const std::uint32_t n3 = neighbour_[prevCorner(c2)], n4 = neighbour_[nextCorner(c2)];
  const EdgeKind k1 = kind_[prevCorner(c)], k2 = kind_[nextCorner(c)];
  const EdgeKind k3 = kind_[prevCorner(c2)], k4 = kind_[nextCorner(c2)];
  setTriangle(t, x, u, y);
  setTriangle(t2, y, w, x);
  link(3 * t, n4, k4);
  link(3 * t + 2, n1, k1);
  link(3 * t2, n2, k2);
  link(3 * t2 + 2, n3, k3);
  link(3 * t + 1, 3 * t2 + 1, EdgeKind::Free);
}

bool Triangulation2D::shouldFlip(std::uint32_t c) const {
  const std::uint32_t across = neighbour_[c];
  if (across == kNone || kind_[c] != EdgeKind::Free) return false;
  const std::uint32_t t = triangleOfCorner(c);
  return incircle(points_[vertex_[3 * t]], points_[vertex_[3 * t + 1]], points_[vertex_[3 * t + 2]],
                  points_[vertex_[across]]) > 0;
}

void Triangulation2D::restoreDelaunay(std::vector<std::uint32_t> stack) {
  while (!stack.empty()) {
    const std::uint32_t c = stack.back();
    stack.pop_back();
    if (!shouldFlip(c)) continue;
    const std::uint32_t c2 = neighbour_[c];
    flip(c);
    const std::uint32_t t = triangleOfCorner(c), t2 = triangleOfCorner(c2);
    stack.insert(stack.end(), {3 * t, 3 * t + 2, 3 * t2, 3 * t2 + 2});
  }
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
