// Segment recovery by Sloan's edge flips, and inside/outside classification of triangles.
#include "mesh/surfaces/constrained_delaunay.h"

#include <deque>
#include <numeric>
#include <optional>
#include <utility>

#include "mesh/core/predicates.h"

namespace geomesh {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

constexpr auto nextCorner = Triangulation2D::nextCorner;
constexpr auto prevCorner = Triangulation2D::prevCorner;

bool pointsAhead(Vec2 a, Vec2 b, Vec2 p) {
  return (b.u - a.u) * (p.u - a.u) + (b.v - a.v) * (p.v - a.v) > 0;
}

// The corner, in a triangle around a, opposite the first edge that segment ab crosses; nullopt
// if a vertex lies on the segment (ab is no edge of the triangulation).
std::optional<std::uint32_t> firstCrossing(const Triangulation2D& tri, std::uint32_t a,
                                           std::uint32_t b) {
  const Vec2 pa = tri.point(a), pb = tri.point(b);
  const std::uint32_t start = tri.triangleOf(a);
  std::uint32_t t = start;
  do {
    std::uint32_t i = 0;
    while (tri.vertex(3 * t + i) != a) ++i;
    const std::uint32_t c = 3 * t + i;
    const Vec2 u = tri.point(tri.vertex(nextCorner(c))), w = tri.point(tri.vertex(prevCorner(c)));
    const int ou = orient2d(pa, pb, u), ow = orient2d(pa, pb, w);
    if (ou == 0 && pointsAhead(pa, pb, u)) return std::nullopt;
    if (ou < 0 && ow > 0) return c;
    const std::uint32_t across = tri.neighbour(prevCorner(c));
    if (across == kNone) return std::nullopt;
    t = across / 3;
  } while (t != start);
  return std::nullopt;
}

// The edges crossed by segment ab, in order from a; nullopt when a vertex lies on the segment
// or a crossed edge is itself constrained.
std::optional<std::vector<Edge>> crossedEdges(const Triangulation2D& tri, std::uint32_t a,
                                              std::uint32_t b) {
  const std::optional<std::uint32_t> first = firstCrossing(tri, a, b);
  if (!first) return std::nullopt;
  const Vec2 pa = tri.point(a), pb = tri.point(b);
  std::vector<Edge> edges;
  std::uint32_t c = *first;
  for (;;) {
    if (tri.kind(c) != EdgeKind::Free || tri.neighbour(c) == kNone) return std::nullopt;
    edges.emplace_back(tri.vertex(nextCorner(c)), tri.vertex(prevCorner(c)));
    const std::uint32_t across = tri.neighbour(c);
    const std::uint32_t y = tri.vertex(across);
    if (y == b) return edges;
    const int oy = orient2d(pa, pb, tri.point(y));
    if (oy == 0) return std::nullopt;
    c = oy < 0 ? prevCorner(across) : nextCorner(across);
  }
}

bool crossesProperly(Vec2 a, Vec2 b, Vec2 x, Vec2 y) {
  return orient2d(a, b, x) * orient2d(a, b, y) < 0 && orient2d(x, y, a) * orient2d(x, y, b) < 0;
}

// Flips the crossed edges away (Sloan's queue): an edge whose quadrilateral is not convex
// waits for its neighbours; a new diagonal still crossing the segment goes back in the queue.
bool flipAway(Triangulation2D& tri, std::uint32_t a, std::uint32_t b, std::vector<Edge> crossing) {
  const Vec2 pa = tri.point(a), pb = tri.point(b);
  std::deque<Edge> queue(crossing.begin(), crossing.end());
  const std::size_t limit = 64 * (queue.size() + 4) * (queue.size() + 4);
  for (std::size_t iteration = 0; !queue.empty(); ++iteration) {
    if (iteration > limit) return false;
    const auto [u, w] = queue.front();
    queue.pop_front();
    const std::uint32_t c = tri.findEdge(u, w);
    if (c == kNone || tri.neighbour(c) == kNone) return false;
    const std::uint32_t x = tri.vertex(c), y = tri.vertex(tri.neighbour(c));
    const Vec2 px = tri.point(x), py = tri.point(y);
    if (orient2d(px, tri.point(u), py) > 0 && orient2d(py, tri.point(w), px) > 0) {
      tri.flip(c);
      if (x != a && x != b && y != a && y != b && crossesProperly(pa, pb, px, py))
        queue.emplace_back(x, y);
    } else {
      queue.emplace_back(u, w);
    }
  }
  return true;
}

bool recoverSegment(Triangulation2D& tri, const ConstrainedSegment& s) {
  if (s.a == s.b) return false;
  std::uint32_t c = tri.findEdge(s.a, s.b);
  if (c == kNone) {
    std::optional<std::vector<Edge>> crossing = crossedEdges(tri, s.a, s.b);
    if (!crossing || !flipAway(tri, s.a, s.b, std::move(*crossing))) return false;
    c = tri.findEdge(s.a, s.b);
    if (c == kNone) return false;
  }
  // A segment given twice keeps the stronger kind (a boundary also used as embedded).
  if (tri.kind(c) != EdgeKind::Boundary) tri.setKind(c, s.kind);
  return true;
}

}  // namespace

long recoverSegments(Triangulation2D& tri, std::span<const ConstrainedSegment> segments) {
  for (std::size_t k = 0; k < segments.size(); ++k)
    if (!recoverSegment(tri, segments[k])) return static_cast<long>(k);
  std::vector<std::uint32_t> all(3 * tri.triangleCount());
  std::iota(all.begin(), all.end(), 0u);
  tri.restoreDelaunay(std::move(all));
  return -1;
}

std::vector<std::uint8_t> classifyInside(const Triangulation2D& tri) {
  // 0-1 breadth-first search: crossing a boundary edge costs one, anything else nothing.
  const std::size_t n = tri.triangleCount();
  std::vector<std::uint32_t> depth(n, kNone);
  std::deque<std::uint32_t> queue;
  const std::uint32_t start = tri.triangleOf(0);
  depth[start] = 0;
  queue.push_back(start);
  while (!queue.empty()) {
    const std::uint32_t t = queue.front();
    queue.pop_front();
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
      const std::uint32_t across = tri.neighbour(c);
      if (across == kNone) continue;
      const std::uint32_t n2 = across / 3;
      const std::uint32_t cost = tri.kind(c) == EdgeKind::Boundary ? 1 : 0;
      if (depth[n2] != kNone && depth[n2] <= depth[t] + cost) continue;
      depth[n2] = depth[t] + cost;
      if (cost == 0)
        queue.push_front(n2);
      else
        queue.push_back(n2);
    }
  }
  std::vector<std::uint8_t> inside(n);
  for (std::size_t t = 0; t < n; ++t) inside[t] = depth[t] != kNone && depth[t] % 2 == 1;
  return inside;
}

}  // namespace geomesh
