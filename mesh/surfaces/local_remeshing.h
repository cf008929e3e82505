// LocalRemesher: edge splits, collapses, swaps and smoothing shared by MeshAdapt and Algorithm 7.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/core/predicates.h"
#include "mesh/surfaces/planar_mesh.h"
#include "mesh/surfaces/triangulation2d.h"

namespace geomesh {

// gamma (twice the inradius over the circumradius) of a work-plane triangle, 0 if it is not
// positive.
double planarGamma(Vec2 a, Vec2 b, Vec2 c);

// (y - x) / log(y / x), the logarithmic mean of two positive numbers (their arithmetic mean
// when they are within a relative 1e-6 of each other).
double logarithmicMean(double x, double y);

// The triangles of `tri` flagged in `inside`, their boundary edges on the hull.
Triangulation2D domainOf(const Triangulation2D& tri, const std::vector<std::uint8_t>& inside);

// The edge operations of meshing by local modifications of a triangulation, over free edges
// only, with vertices below `firstMovable` fixed. Passes split edges longer than `splitAbove`
// at their middle (longest first), collapse those shorter than `collapseBelow` (shortest
// first), swap edges for quality and smooth vertices; between passes only what changed in the
// pass or the one before is looked at again.
//
// Mesher (deriving from LocalRemesher<Mesher>) supplies:
//   double length(uint32_t a, uint32_t b) const  the edge's length, 1 being the target;
//   double quality(uint32_t a, uint32_t b, uint32_t c, Vec2 pa, Vec2 pb, Vec2 pc) const
//       the quality of the triangle of vertices a, b, c placed at pa, pb, pc;
//   uint32_t insertSplitVertex(uint32_t corner, Vec2 m)  adds the point m, splits the edge
//       opposite `corner` there and sets up the new vertex's data; returns the new vertex;
//   bool smoothingPlace(uint32_t v, uint32_t w, Vec2& place) const  where v should go
//       according to its neighbour w (false: leave v where it is);
//   void afterSmoothing(uint32_t v, Vec2 old, Vec2 p)  v moved from old to p (ring_ holds
//       the corners around v): updates its data and touches what changed.
template <class Mesher>
class LocalRemesher {
 protected:
  static constexpr int kMaxPasses = 40;
  // The passes stop when this many in a row leave at least as many edges out of range.
  static constexpr int kPassesWithoutProgress = 3;
  // A collapse may lower the quality of the triangles around it down to this, no further.
  static constexpr double kCollapseQuality = 0.2;

  struct Edge {
    double length;
    std::uint32_t a, b;
  };
  struct Range {
    std::size_t outside = 0;  // free edges out of range
    double longest = 0;
  };

  LocalRemesher(Triangulation2D mesh, std::uint32_t firstMovable, double splitAbove,
                double collapseBelow)
      : mesh_(std::move(mesh)),
        firstMovable_(firstMovable),
        splitAbove_(splitAbove),
        collapseBelow_(collapseBelow),
        mark_(mesh_.pointCount(), 0),
        touched_(mesh_.pointCount(), 0) {}

  static constexpr auto nextCorner = Triangulation2D::nextCorner;
  static constexpr auto prevCorner = Triangulation2D::prevCorner;

  // Room for the per-vertex data of vertices up to n - 1.
  void growVertexData(std::size_t n) {
    mark_.resize(std::max(n, mark_.size()), 0);
    touched_.resize(std::max(n, touched_.size()), 0);
  }
  void touch(std::uint32_t v) { touched_[v] = pass_; }
  // Whether v changed, or a neighbour of v moved, in this pass or the previous one: the rest
  // of the mesh is as swaps and smoothing left it.
  bool recent(std::uint32_t v) const { return everywhere_ || touched_[v] + 1 >= pass_; }
  double quality(std::uint32_t t) const {
    const std::uint32_t a = mesh_.vertex(3 * t), b = mesh_.vertex(3 * t + 1),
                        c = mesh_.vertex(3 * t + 2);
    return self().quality(a, b, c, mesh_.point(a), mesh_.point(b), mesh_.point(c));
  }

  // One pass of splits, collapses, swaps, smoothing and swaps again.
  void modifyOnce() {
    splitLongEdges();
    collapseShortEdges();
    swapEdges();
    smoothVertices();
    swapEdges();
  }
  // Passes of smoothing and swaps over the whole mesh.
  void smoothAll(int passes) {
    everywhere_ = true;
    for (int pass = 0; pass < passes; ++pass) {
      smoothVertices();
      swapEdges();
    }
  }
  Range range() const;
  // The triangles of the mesh, appended to out.triangles.
  void appendTriangles(PlanarMesh& out) const {
    for (std::uint32_t t = 0; t < mesh_.triangleCount(); ++t)
      if (mesh_.alive(t))
        for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) out.triangles.push_back(mesh_.vertex(c));
  }

  Triangulation2D mesh_;
  std::uint32_t firstMovable_;
  double splitAbove_, collapseBelow_;
  std::vector<std::uint32_t> mark_;  // per vertex: stamps of the link test
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> touched_;  // per vertex: the last pass that changed it
  std::uint32_t pass_ = 1;
  bool everywhere_ = true;  // swaps, smoothing and edge checks go over the whole mesh
  std::vector<std::uint32_t> ring_, otherRing_;

 private:
  const Mesher& self() const { return static_cast<const Mesher&>(*this); }
  Mesher& self() { return static_cast<Mesher&>(*this); }
  template <class F>
  void forEachFreeEdge(F f) const;
  std::vector<Edge> edgesOutside(bool longOnes) const;
  void splitLongEdges();
  void split(std::uint32_t corner);
  void collapseShortEdges();
  bool tryCollapse(std::uint32_t v, std::uint32_t w);
  void swapEdges();
  bool swapImproves(std::uint32_t corner) const;
  void smoothVertices();
  void smoothVertex(std::uint32_t v);
  double worstAround(std::uint32_t v, Vec2 p) const;
  bool allPositiveAround(Vec2 p) const;
};

// Calls f(a, b) for each free edge once.
template <class Mesher>
template <class F>
void LocalRemesher<Mesher>::forEachFreeEdge(F f) const {
  for (std::uint32_t t = 0; t < mesh_.triangleCount(); ++t) {
    if (!mesh_.alive(t)) continue;
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
      const std::uint32_t across = mesh_.neighbour(c);
      if (across != kNone && across > c && mesh_.kind(c) == EdgeKind::Free)
        f(mesh_.vertex(nextCorner(c)), mesh_.vertex(prevCorner(c)));
    }
  }
}

// Free edges near recent changes longer than the split length (longOnes) or shorter than the
// collapse length, longest (shortest) first. The others were out of range already in the
// previous pass, and could not be split or collapsed then.
template <class Mesher>
auto LocalRemesher<Mesher>::edgesOutside(bool longOnes) const -> std::vector<Edge> {
  std::vector<Edge> edges;
  forEachFreeEdge([&](std::uint32_t a, std::uint32_t b) {
    if (!recent(a) && !recent(b)) return;
    const double l = self().length(a, b);
    if (longOnes ? l > splitAbove_ : l < collapseBelow_) edges.push_back({l, a, b});
  });
  const auto key = [](const Edge& e) { return std::tuple(e.length, e.a, e.b); };
  std::sort(edges.begin(), edges.end(), [&](const Edge& x, const Edge& y) {
    return longOnes ? key(y) < key(x) : key(x) < key(y);
  });
  return edges;
}

template <class Mesher>
auto LocalRemesher<Mesher>::range() const -> Range {
  Range r;
  forEachFreeEdge([&](std::uint32_t a, std::uint32_t b) {
    const double l = self().length(a, b);
    r.outside += l > splitAbove_ || l < collapseBelow_;
    r.longest = std::max(r.longest, l);
  });
  return r;
}

template <class Mesher>
void LocalRemesher<Mesher>::splitLongEdges() {
  for (const Edge& e : edgesOutside(true)) {
    const std::uint32_t c = mesh_.findUndirectedEdge(e.a, e.b);
    if (c != kNone && mesh_.kind(c) == EdgeKind::Free) split(c);
  }
}

template <class Mesher>
void LocalRemesher<Mesher>::split(std::uint32_t c) {
  const std::uint32_t x = mesh_.vertex(c), u = mesh_.vertex(nextCorner(c)),
                      w = mesh_.vertex(prevCorner(c)), y = mesh_.vertex(mesh_.neighbour(c));
  const Vec2 px = mesh_.point(x), pu = mesh_.point(u), pw = mesh_.point(w), py = mesh_.point(y);
  const Vec2 m{0.5 * (pu.u + pw.u), 0.5 * (pu.v + pw.v)};
  // Rounding may put the midpoint off the edge: every new triangle must stay positive.
  if (orient2d(px, pu, m) <= 0 || orient2d(px, m, pw) <= 0 || orient2d(py, pw, m) <= 0 ||
      orient2d(py, m, pu) <= 0)
    return;
  const std::uint32_t v = self().insertSplitVertex(c, m);
  for (std::uint32_t changed : {x, u, w, y, v}) touch(changed);
}

template <class Mesher>
void LocalRemesher<Mesher>::collapseShortEdges() {
  for (const Edge& e : edgesOutside(false)) {
    if (!mesh_.inMesh(e.a) || !mesh_.inMesh(e.b) || mesh_.findUndirectedEdge(e.a, e.b) == kNone)
      continue;
    if (!tryCollapse(e.a, e.b)) tryCollapse(e.b, e.a);
  }
}

// Merges v into w if v may move, the result is a valid triangulation (the link condition:
// v and w have exactly two common neighbours; every triangle stays positive) and it makes
// no long edge nor a bad triangle.
template <class Mesher>
bool LocalRemesher<Mesher>::tryCollapse(std::uint32_t v, std::uint32_t w) {
  if (v < firstMovable_ || !mesh_.ring(v, ring_)) return false;
  ++stamp_;
  for (std::uint32_t c : ring_) mark_[mesh_.vertex(nextCorner(c))] = stamp_;
  const bool wClosed = mesh_.ring(w, otherRing_);
  int common = 0;
  for (std::uint32_t c : otherRing_) common += mark_[mesh_.vertex(nextCorner(c))] == stamp_;
  if (!wClosed) common += mark_[mesh_.vertex(prevCorner(otherRing_.back()))] == stamp_;
  if (common != 2) return false;
  const Vec2 pw = mesh_.point(w);
  double oldWorst = 1, newWorst = 1;
  for (std::uint32_t c : ring_) {
    oldWorst = std::min(oldWorst, quality(c / 3));
    const std::uint32_t b = mesh_.vertex(nextCorner(c)), a = mesh_.vertex(prevCorner(c));
    if (a == w || b == w) continue;
    const Vec2 pb = mesh_.point(b), pa = mesh_.point(a);
    if (orient2d(pw, pb, pa) <= 0 || self().length(w, b) > splitAbove_) return false;
    newWorst = std::min(newWorst, self().quality(w, b, a, pw, pb, pa));
  }
  if (newWorst < std::min(oldWorst, kCollapseQuality)) return false;
  for (std::uint32_t c : ring_) touch(mesh_.vertex(nextCorner(c)));
  mesh_.collapse(v, w, ring_);
  return true;
}

// Lawson-style swaps for quality: an edge is swapped when the worse of its two triangles
// gets better. Each swap raises the sorted list of qualities, so the loop ends.
template <class Mesher>
void LocalRemesher<Mesher>::swapEdges() {
  std::vector<std::uint32_t> stack;
  for (std::uint32_t t = 0; t < mesh_.triangleCount(); ++t) {
    if (!mesh_.alive(t) || !(recent(mesh_.vertex(3 * t)) || recent(mesh_.vertex(3 * t + 1)) ||
                             recent(mesh_.vertex(3 * t + 2))))
      continue;
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c)
      if (mesh_.neighbour(c) != kNone && mesh_.neighbour(c) > c) stack.push_back(c);
  }
  std::reverse(stack.begin(), stack.end());
  mesh_.flipWhile(std::move(stack), [this](std::uint32_t c) {
    if (!swapImproves(c)) return false;
    touch(mesh_.vertex(c)), touch(mesh_.vertex(mesh_.neighbour(c)));
    return true;
  });
}

template <class Mesher>
bool LocalRemesher<Mesher>::swapImproves(std::uint32_t c) const {
  const std::uint32_t across = mesh_.neighbour(c);
  if (across == kNone || mesh_.kind(c) != EdgeKind::Free) return false;
  const std::uint32_t ix = mesh_.vertex(c), iu = mesh_.vertex(nextCorner(c)),
                      iw = mesh_.vertex(prevCorner(c)), iy = mesh_.vertex(across);
  const Vec2 x = mesh_.point(ix), u = mesh_.point(iu), w = mesh_.point(iw), y = mesh_.point(iy);
  const Mesher& m = self();
  const double before = std::min(m.quality(ix, iu, iw, x, u, w), m.quality(iy, iw, iu, y, w, u));
  const double after = std::min(m.quality(ix, iu, iy, x, u, y), m.quality(iy, iw, ix, y, w, x));
  // The exact test last: it only confirms what the qualities, 0 if not positive, suggest.
  return after > before * (1 + 1e-3) && orient2d(x, u, y) > 0 && orient2d(y, w, x) > 0;
}

template <class Mesher>
void LocalRemesher<Mesher>::smoothVertices() {
  for (std::uint32_t v = firstMovable_; v < mesh_.pointCount(); ++v)
    if (mesh_.inMesh(v) && recent(v)) smoothVertex(v);
}

// Moves v towards the mean of the places its neighbours ask for, as far as keeps every
// triangle around it positive and the worst of them no worse.
template <class Mesher>
void LocalRemesher<Mesher>::smoothVertex(std::uint32_t v) {
  if (!mesh_.ring(v, ring_)) return;
  const Vec2 old = mesh_.point(v);
  double su = 0, sv = 0, worst = 1;
  for (std::uint32_t c : ring_) {
    Vec2 place;
    if (!self().smoothingPlace(v, mesh_.vertex(nextCorner(c)), place)) return;
    su += place.u, sv += place.v;
    worst = std::min(worst, quality(c / 3));
  }
  const Vec2 target{su / ring_.size(), sv / ring_.size()};
  for (double step : {1.0, 0.5, 0.25}) {
    const Vec2 p{old.u + step * (target.u - old.u), old.v + step * (target.v - old.v)};
    if (worstAround(v, p) >= worst && allPositiveAround(p)) {
      mesh_.movePoint(v, p);
      self().afterSmoothing(v, old, p);
      return;
    }
  }
}

// The worst quality of the triangles of ring_ with their common vertex v at p.
template <class Mesher>
double LocalRemesher<Mesher>::worstAround(std::uint32_t v, Vec2 p) const {
  double worst = 1;
  for (std::uint32_t c : ring_) {
    const std::uint32_t b = mesh_.vertex(nextCorner(c)), a = mesh_.vertex(prevCorner(c));
    worst = std::min(worst, self().quality(v, b, a, p, mesh_.point(b), mesh_.point(a)));
  }
  return worst;
}

template <class Mesher>
bool LocalRemesher<Mesher>::allPositiveAround(Vec2 p) const {
  for (std::uint32_t c : ring_)
    if (orient2d(p, mesh_.point(mesh_.vertex(nextCorner(c))),
                 mesh_.point(mesh_.vertex(prevCorner(c)))) <= 0)
      return false;
  return true;
}

}  // namespace geomesh
