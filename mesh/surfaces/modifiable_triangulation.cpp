#include "mesh/surfaces/modifiable_triangulation.h"

namespace geomesh {

ModifiableTriangulation::ModifiableTriangulation(const Triangulation2D& tri,
                                                 const std::vector<std::uint8_t>& inside)
    : points_(tri.points().begin(), tri.points().end()), triangleOf_(tri.pointCount(), kNone) {
  std::vector<std::uint32_t> index(tri.triangleCount(), kNone);
  std::uint32_t count = 0;
  for (std::uint32_t t = 0; t < tri.triangleCount(); ++t)
    if (inside[t]) index[t] = count++;
  vertex_.resize(3 * count);
  neighbour_.resize(3 * count);
  kind_.resize(3 * count);
  alive_.assign(count, 1);
  for (std::uint32_t t = 0; t < tri.triangleCount(); ++t) {
    if (!inside[t]) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t c = 3 * index[t] + i;
      const std::uint32_t across = tri.neighbour(3 * t + i);
      vertex_[c] = tri.vertex(3 * t + i);
      neighbour_[c] = across != kNone && inside[across / 3] ? 3 * index[across / 3] + across % 3
                                                            : kNone;
      kind_[c] = tri.kind(3 * t + i);
      triangleOf_[vertex_[c]] = index[t];
    }
  }
}

bool ModifiableTriangulation::ring(std::uint32_t v, std::vector<std::uint32_t>& corners) const {
  corners.clear();
  const std::uint32_t first = cornerOf(triangleOf_[v], v);
  // Turn clockwise to the boundary, if there is one: the walk starts there.
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

std::uint32_t ModifiableTriangulation::findEdge(std::uint32_t a, std::uint32_t b) const {
  if (triangleOf_[a] == kNone) return kNone;
  ring(a, scratch_);
  for (std::uint32_t c : scratch_) {
    if (vertex_[nextCorner(c)] == b) return prevCorner(c);
    if (vertex_[prevCorner(c)] == b) return nextCorner(c);
  }
  return kNone;
}

std::uint32_t ModifiableTriangulation::newTriangle() {
  if (!free_.empty()) {
    const std::uint32_t t = free_.back();
    free_.pop_back();
    alive_[t] = 1;
    return t;
  }
  vertex_.resize(vertex_.size() + 3);
  neighbour_.resize(neighbour_.size() + 3);
  kind_.resize(kind_.size() + 3);
  alive_.push_back(1);
  return static_cast<std::uint32_t>(alive_.size() - 1);
}

void ModifiableTriangulation::setTriangle(std::uint32_t t, std::uint32_t a, std::uint32_t b,
                                          std::uint32_t c) {
  vertex_[3 * t] = a, vertex_[3 * t + 1] = b, vertex_[3 * t + 2] = c;
  triangleOf_[a] = triangleOf_[b] = triangleOf_[c] = t;
}

void ModifiableTriangulation::link(std::uint32_t c1, std::uint32_t c2, EdgeKind k) {
  neighbour_[c1] = c2;
  kind_[c1] = k;
  if (c2 != kNone) neighbour_[c2] = c1, kind_[c2] = k;
}

// The edge (u, w) of corner e, with triangles (x, u, w) and (y, w, u), gets its midpoint m:
// (x, u, m), (x, m, w), (y, w, m), (y, m, u).
void ModifiableTriangulation::split(std::uint32_t e, std::uint32_t m) {
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

// (x, u, w) and (y, w, u) become (x, u, y) and (y, w, x).
void ModifiableTriangulation::flip(std::uint32_t e) {
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

void ModifiableTriangulation::collapse(std::uint32_t v, std::uint32_t w,
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
      free_.push_back(c / 3);
    }
  }
  for (std::uint32_t c : ringOfV)
    if (alive_[c / 3]) {
      vertex_[c] = w;
      setTriangle(c / 3, vertex_[c - c % 3], vertex_[c - c % 3 + 1], vertex_[c - c % 3 + 2]);
    }
  for (int k = 0; k < removed; ++k) link(seams[k].inner, seams[k].outer, seams[k].kind);
  triangleOf_[v] = kNone;
}

}  // namespace geomesh
