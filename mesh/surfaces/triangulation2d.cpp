// Triangulation2D: storage, adjacency queries and the local operations (flip, split, collapse).
#include "mesh/surfaces/triangulation2d.h"

#include <algorithm>
#include <cmath>

namespace geomesh {

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
  alive_.assign(1, 1);
  mark_.assign(1, 0);
  vertexTriangle_ = {0, 0, 0};
}

std::uint32_t Triangulation2D::addPoint(Vec2 p) {
  points_.push_back(p);
  sizes_.push_back(0);
  vertexTriangle_.push_back(kNone);
  return static_cast<std::uint32_t>(points_.size() - 1);
}

void Triangulation2D::removeLastPoint() {
  if (points_.empty() || vertexTriangle_.back() != kNone) return;
  points_.pop_back();
  sizes_.pop_back();
  vertexTriangle_.pop_back();
}

void Triangulation2D::setKind(std::uint32_t corner, EdgeKind k) {
  kind_[corner] = k;
  if (neighbour_[corner] != kNone) kind_[neighbour_[corner]] = k;
}

std::uint32_t Triangulation2D::newTriangle() {
  if (!dead_.empty()) {
    const std::uint32_t t = dead_.back();
    dead_.pop_back();
    alive_[t] = 1;
    return t;
  }
  vertex_.resize(vertex_.size() + 3);
  neighbour_.resize(neighbour_.size() + 3);
  kind_.resize(kind_.size() + 3);
  alive_.push_back(1);
  mark_.push_back(0);
  return static_cast<std::uint32_t>(alive_.size() - 1);
}

void Triangulation2D::setTriangle(std::uint32_t t, std::uint32_t a, std::uint32_t b,
                                  std::uint32_t c) {
  vertex_[3 * t] = a, vertex_[3 * t + 1] = b, vertex_[3 * t + 2] = c;
  vertexTriangle_[a] = vertexTriangle_[b] = vertexTriangle_[c] = t;
}

void Triangulation2D::link(std::uint32_t c1, std::uint32_t c2, EdgeKind k) {
  neighbour_[c1] = c2;
  kind_[c1] = k;
  if (c2 != kNone) neighbour_[c2] = c1, kind_[c2] = k;
}

std::uint32_t Triangulation2D::findEdge(std::uint32_t a, std::uint32_t b) const {
  const std::uint32_t start = vertexTriangle_[a];
  if (start == kNone) return kNone;
  // Turn around a one way, then, if the hull stops us, the other way.
  for (int direction = 0; direction < 2; ++direction) {
    std::uint32_t t = start;
    bool hitHull = false;
    do {
      const std::uint32_t c = cornerOf(t, a);
      if (vertex_[nextCorner(c)] == b) return prevCorner(c);
      const std::uint32_t across =
          direction == 0 ? neighbour_[prevCorner(c)] : neighbour_[nextCorner(c)];
      if (across == kNone) {
        hitHull = true;
        break;
      }
      t = across / 3;
    } while (t != start);
    if (!hitHull) return kNone;
  }
  return kNone;
}

std::uint32_t Triangulation2D::findUndirectedEdge(std::uint32_t a, std::uint32_t b) const {
  if (vertexTriangle_[a] == kNone) return kNone;
  ring(a, scratch_);
  for (std::uint32_t c : scratch_) {
    if (vertex_[nextCorner(c)] == b) return prevCorner(c);
    if (vertex_[prevCorner(c)] == b) return nextCorner(c);
  }
  return kNone;
}

bool Triangulation2D::ring(std::uint32_t v, std::vector<std::uint32_t>& corners) const {
  corners.clear();
  const std::uint32_t first = cornerOf(vertexTriangle_[v], v);
  // Turn clockwise to the hull, if v is on it: the walk starts there.
  std::uint32_t start = first;
  bool closed = true;
  for (;;) {
    const std::uint32_t across = neighbour_[prevCorner(start)];
    if (across == kNone) {
      closed = false;
      break;
    }
    const std::uint32_t c = cornerOf(across / 3, v);
    if (c == first) break;
    start = c;
  }
  std::uint32_t c = closed ? first : start;
  for (;;) {
    corners.push_back(c);
    const std::uint32_t across = neighbour_[nextCorner(c)];
    if (across == kNone) break;
    c = cornerOf(across / 3, v);
    if (c == corners.front()) break;
  }
  return closed;
}

// (x, u, w) and (y, w, u), sharing the edge of corner e, become (x, u, y) and (y, w, x).
void Triangulation2D::flip(std::uint32_t e) {
  const std::uint32_t e2 = neighbour_[e];
  const std::uint32_t x = vertex_[e], u = vertex_[nextCorner(e)], w = vertex_[prevCorner(e)];
  const std::uint32_t y = vertex_[e2];
  const std::uint32_t xu = neighbour_[prevCorner(e)], wx = neighbour_[nextCorner(e)];
  const std::uint32_t yw = neighbour_[prevCorner(e2)], uy = neighbour_[nextCorner(e2)];
  const EdgeKind kxu = kind_[prevCorner(e)], kwx = kind_[nextCorner(e)];
  const EdgeKind kyw = kind_[prevCorner(e2)], kuy = kind_[nextCorner(e2)];
  const std::uint32_t t1 = e / 3, t2 = e2 / 3;
  setTriangle(t1, x, u, y);
  setTriangle(t2, y, w, x);
  link(3 * t1, uy, kuy);
  link(3 * t1 + 1, 3 * t2 + 1, EdgeKind::Free);
  link(3 * t1 + 2, xu, kxu);
  link(3 * t2, wx, kwx);
  link(3 * t2 + 2, yw, kyw);
}

// The edge (u, w) of corner e, with triangles (x, u, w) and (y, w, u), gets vertex m:
// (x, u, m), (x, m, w), (y, w, m), (y, m, u).
void Triangulation2D::split(std::uint32_t e, std::uint32_t m) {
  const std::uint32_t e2 = neighbour_[e];
  const std::uint32_t x = vertex_[e], u = vertex_[nextCorner(e)], w = vertex_[prevCorner(e)];
  const std::uint32_t y = vertex_[e2];
  const std::uint32_t xu = neighbour_[prevCorner(e)], wx = neighbour_[nextCorner(e)];
  const std::uint32_t yw = neighbour_[prevCorner(e2)], uy = neighbour_[nextCorner(e2)];
  const EdgeKind kxu = kind_[prevCorner(e)], kwx = kind_[nextCorner(e)];
  const EdgeKind kyw = kind_[prevCorner(e2)], kuy = kind_[nextCorner(e2)];
  const std::uint32_t a = e / 3, c = e2 / 3, b = newTriangle(), d = newTriangle();
  setTriangle(a, x, u, m);
  setTriangle(b, x, m, w);
  setTriangle(c, y, w, m);
  setTriangle(d, y, m, u);
  link(3 * a, 3 * d, EdgeKind::Free);
  link(3 * a + 1, 3 * b + 2, EdgeKind::Free);
  link(3 * a + 2, xu, kxu);
  link(3 * b, 3 * c, EdgeKind::Free);
  link(3 * b + 1, wx, kwx);
  link(3 * c + 1, 3 * d + 2, EdgeKind::Free);
  link(3 * c + 2, yw, kyw);
  link(3 * d + 1, uy, kuy);
}

void Triangulation2D::collapse(std::uint32_t v, std::uint32_t w,
                               const std::vector<std::uint32_t>& ringOfV) {
  // A removed triangle's two other edges become one: the corners across them get linked.
  struct Seam {
    std::uint32_t inner, outer;
    EdgeKind kind;
  };
  Seam seams[2];
  int removed = 0;
  for (std::uint32_t c : ringOfV) {
    // Triangle (v, b, a), counter-clockwise.
    const std::uint32_t b = vertex_[nextCorner(c)], a = vertex_[prevCorner(c)];
    if (b == w)
      seams[removed++] = {neighbour_[nextCorner(c)], neighbour_[c], kind_[c]};
    else if (a == w)
      seams[removed++] = {neighbour_[prevCorner(c)], neighbour_[c], kind_[c]};
    if (b == w || a == w) {
      alive_[c / 3] = 0;
      dead_.push_back(c / 3);
    }
  }
  for (std::uint32_t c : ringOfV)
    if (alive_[c / 3]) {
      vertex_[c] = w;
      setTriangle(c / 3, vertex_[c - c % 3], vertex_[c - c % 3 + 1], vertex_[c - c % 3 + 2]);
    }
  for (int k = 0; k < removed; ++k) link(seams[k].inner, seams[k].outer, seams[k].kind);
  vertexTriangle_[v] = kNone;
}

void Triangulation2D::keepTriangles(const std::vector<std::uint8_t>& keep) {
  const std::uint32_t n = static_cast<std::uint32_t>(triangleCount());
  std::vector<std::uint32_t> index(n, kNone);
  std::uint32_t count = 0;
  for (std::uint32_t t = 0; t < n; ++t)
    if (keep[t]) index[t] = count++;
  std::vector<std::uint32_t> vertex(3 * count), neighbour(3 * count);
  std::vector<EdgeKind> kind(3 * count);
  vertexTriangle_.assign(points_.size(), kNone);
  for (std::uint32_t t = 0; t < n; ++t) {
    if (!keep[t]) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t c = 3 * index[t] + i;
      const std::uint32_t across = neighbour_[3 * t + i];
      vertex[c] = vertex_[3 * t + i];
      neighbour[c] = across != kNone && keep[across / 3] ? 3 * index[across / 3] + across % 3
                                                         : kNone;
      kind[c] = kind_[3 * t + i];
      vertexTriangle_[vertex[c]] = index[t];
    }
  }
  vertex_ = std::move(vertex);
  neighbour_ = std::move(neighbour);
  kind_ = std::move(kind);
  alive_.assign(count, 1);
  mark_.assign(count, 0);
  dead_.clear();
  cavity_.clear(), created_.clear(), rim_.clear(), rimEdges_.clear();
}

}  // namespace geomesh
