// MeshAdapter: passes of edge splits, collapses, swaps and smoothing until edges fit the size.
#include "mesh/surfaces/mesh_adapt.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "mesh/core/predicates.h"

namespace geomesh {
namespace {

// An edge is split above this length and collapsed below that one, in target sizes. With a
// ratio of 2 between them, halving a long edge never makes a collapsible one.
constexpr double kSplitAbove = 1.4;
constexpr double kCollapseBelow = 0.7;
constexpr int kMaxPasses = 40;
// The passes stop when this many in a row leave at least as many edges out of range.
constexpr int kPassesWithoutProgress = 3;
// A collapse may lower the quality of the triangles around it down to this, no further.
constexpr double kCollapseQuality = 0.2;
// A vertex that smoothing moves by less than this fraction of the target size has settled.
constexpr double kSettled = 0.02;

constexpr auto nextCorner = Triangulation2D::nextCorner;
constexpr auto prevCorner = Triangulation2D::prevCorner;

Vec2 sub(Vec2 a, Vec2 b) {
  return {a.u - b.u, a.v - b.v};
}
double norm(Vec2 a) {
  return std::sqrt(a.u * a.u + a.v * a.v);
}
Vec2 midpoint(Vec2 a, Vec2 b) {
  return {0.5 * (a.u + b.u), 0.5 * (a.v + b.v)};
}

// The size to divide a length by to count it in target sizes, for an edge whose ends ask
// for ha and hb with the size varying linearly between them (1 / the mean of 1 / h).
double edgeSize(double ha, double hb) {
  if (std::abs(ha - hb) <= 1e-6 * (ha + hb)) return 0.5 * (ha + hb);
  return (hb - ha) / std::log(hb / ha);
}

// gamma (twice the inradius over the circumradius) of a triangle, 0 if it is not positive.
double gamma(Vec2 a, Vec2 b, Vec2 c) {
  const double area = 0.5 * ((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
  if (!(area > 0)) return 0;
  const double la = norm(sub(c, b)), lb = norm(sub(a, c)), lc = norm(sub(b, a));
  return 16 * area * area / (la * lb * lc * (la + lb + lc));
}

// Target sizes extended from the boundary: linear over the triangles of the boundary's
// constrained triangulation, as a background mesh.
class BoundarySizes {
 public:
  BoundarySizes(const Triangulation2D& tri, const std::vector<std::uint8_t>& inside)
      : tri_(tri), inside_(inside) {}

  // The size at x; `hint` is a domain triangle to start the search from, and becomes the
  // one x lies in.
  double at(Vec2 x, std::uint32_t& hint) {
    const std::uint32_t t = tri_.locate(x, hint);
    if (t != kNone && inside_[t]) hint = t;
    const std::uint32_t v[3] = {tri_.vertex(3 * hint), tri_.vertex(3 * hint + 1),
                                tri_.vertex(3 * hint + 2)};
    const Vec2 a = tri_.point(v[0]), b = tri_.point(v[1]), c = tri_.point(v[2]);
    const double det = (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
    double l1 = ((x.u - a.u) * (c.v - a.v) - (x.v - a.v) * (c.u - a.u)) / det;
    double l2 = ((b.u - a.u) * (x.v - a.v) - (b.v - a.v) * (x.u - a.u)) / det;
    double l0 = 1 - l1 - l2;
    // Rounding may put x a hair outside: clamp to the triangle.
    l0 = std::max(l0, 0.0), l1 = std::max(l1, 0.0), l2 = std::max(l2, 0.0);
    const double sum = l0 + l1 + l2;
    return (l0 * tri_.size(v[0]) + l1 * tri_.size(v[1]) + l2 * tri_.size(v[2])) / sum;
  }

 private:
  Triangulation2D tri_;  // a copy: locate() draws its own random numbers
  const std::vector<std::uint8_t>& inside_;
};

// The domain's part of a triangulation: its boundary edges on the hull.
Triangulation2D domainOf(const Triangulation2D& tri, const std::vector<std::uint8_t>& inside) {
  Triangulation2D domain = tri;
  domain.keepTriangles(inside);
  return domain;
}

struct Edge {
  double length;  // in target sizes
  std::uint32_t a, b;
};

class MeshAdapter {
 public:
  MeshAdapter(const Triangulation2D& boundary, const std::vector<std::uint8_t>& inside,
              std::uint32_t firstMovable, const SurfaceMetric* metric,
              const WorkPlaneSize* field)
      : mesh_(domainOf(boundary, inside)), background_(boundary, inside), metric_(metric),
        field_(field), firstMovable_(firstMovable), target_(boundary.pointCount()),
        hint_(boundary.pointCount(), kNone), mark_(boundary.pointCount(), 0),
        touched_(boundary.pointCount(), 0) {
    for (std::uint32_t t = 0; t < boundary.triangleCount(); ++t)
      if (inside[t])
        for (int i = 0; i < 3; ++i) hint_[boundary.vertex(3 * t + i)] = t;
    for (std::uint32_t v = 0; v < boundary.pointCount(); ++v) {
      const double size = mesh_.size(v);
      target_[v] = mesh_.inMesh(v) ? cappedByField(size, mesh_.point(v)) : size;
    }
  }

  PlanarMesh run(int smoothingPasses);

 private:
  double metricLength(Vec2 a, Vec2 b) const;
  double length(std::uint32_t a, std::uint32_t b) const {
    return metricLength(mesh_.point(a), mesh_.point(b)) / edgeSize(target_[a], target_[b]);
  }
  double quality(Vec2 a, Vec2 b, Vec2 c) const;
  double quality(std::uint32_t t) const {
    return quality(mesh_.point(mesh_.vertex(3 * t)), mesh_.point(mesh_.vertex(3 * t + 1)),
                   mesh_.point(mesh_.vertex(3 * t + 2)));
  }
  void updateSize(std::uint32_t v);
  double cappedByField(double size, Vec2 x) const;
  template <class F>
  void forEachFreeEdge(F f) const;
  std::vector<Edge> edgesOutside(bool longOnes) const;
  struct Range {
    std::size_t outside = 0;  // free edges out of range
    double longest = 0;
  };
  Range range() const;
  void splitLongEdges();
  void split(std::uint32_t corner);
  void collapseShortEdges();
  bool tryCollapse(std::uint32_t v, std::uint32_t w);
  void touch(std::uint32_t v) { touched_[v] = pass_; }
  // Whether v changed, or a neighbour of v moved, in this pass or the previous one: the
  // rest of the mesh is as swaps and smoothing left it.
  bool recent(std::uint32_t v) const { return everywhere_ || touched_[v] + 1 >= pass_; }
  void swapEdges();
  bool swapImproves(std::uint32_t corner) const;
  void smoothVertices();
  void smoothVertex(std::uint32_t v);
  double worstAround(Vec2 p, const std::vector<std::uint32_t>& ring) const;
  bool allPositiveAround(Vec2 p, const std::vector<std::uint32_t>& ring) const;
  PlanarMesh result() const;

  Triangulation2D mesh_;  // the domain only; its sizes are those extended from the boundary
  BoundarySizes background_;
  const SurfaceMetric* metric_;
  const WorkPlaneSize* field_;
  std::uint32_t firstMovable_;
  std::vector<double> target_;       // per vertex: the size asked for (field included)
  std::vector<std::uint32_t> hint_;  // per vertex: where its size was found in background_
  std::vector<std::uint32_t> mark_;  // per vertex: stamps of the link test
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> touched_;  // per vertex: the last pass that changed it
  std::uint32_t pass_ = 1;
  bool everywhere_ = true;  // swaps and smoothing go over the whole mesh
  std::vector<std::uint32_t> ring_, otherRing_;
};

double MeshAdapter::metricLength(Vec2 a, Vec2 b) const {
  const double du = b.u - a.u, dv = b.v - a.v;
  if (!metric_) return std::sqrt(du * du + dv * dv);
  const Metric2 m = metric_->at(midpoint(a, b));
  return std::sqrt(std::max(m.a * du * du + 2 * m.b * du * dv + m.c * dv * dv, 0.0));
}

double MeshAdapter::quality(Vec2 a, Vec2 b, Vec2 c) const {
  if (!metric_) return gamma(a, b, c);
  const MetricFrame f(metric_->at({(a.u + b.u + c.u) / 3, (a.v + b.v + c.v) / 3}));
  return gamma(f.apply(a), f.apply(b), f.apply(c));
}

void MeshAdapter::updateSize(std::uint32_t v) {
  const Vec2 x = mesh_.point(v);
  mesh_.setSize(v, background_.at(x, hint_[v]));
  target_[v] = cappedByField(mesh_.size(v), x);
}

// A field's size where it asks for one (a size that is not positive asks for nothing).
double MeshAdapter::cappedByField(double size, Vec2 x) const {
  if (!field_) return size;
  const double f = (*field_)(x);
  return f > 0 ? std::min(size, f) : size;
}

// Calls f(a, b) for each free edge once.
template <class F>
void MeshAdapter::forEachFreeEdge(F f) const {
  for (std::uint32_t t = 0; t < mesh_.triangleCount(); ++t) {
    if (!mesh_.alive(t)) continue;
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
      const std::uint32_t across = mesh_.neighbour(c);
      if (across != kNone && across > c && mesh_.kind(c) == EdgeKind::Free)
        f(mesh_.vertex(nextCorner(c)), mesh_.vertex(prevCorner(c)));
    }
  }
}

// Free edges near recent changes longer than the split length (longOnes) or shorter than
// the collapse length, longest (shortest) first. The others were out of range already in
// the previous pass, and could not be split or collapsed then.
std::vector<Edge> MeshAdapter::edgesOutside(bool longOnes) const {
  std::vector<Edge> edges;
  forEachFreeEdge([&](std::uint32_t a, std::uint32_t b) {
    if (!recent(a) && !recent(b)) return;
    const double l = length(a, b);
    if (longOnes ? l > kSplitAbove : l < kCollapseBelow) edges.push_back({l, a, b});
  });
  const auto key = [](const Edge& e) { return std::tuple(e.length, e.a, e.b); };
  std::sort(edges.begin(), edges.end(), [&](const Edge& x, const Edge& y) {
    return longOnes ? key(y) < key(x) : key(x) < key(y);
  });
  return edges;
}

MeshAdapter::Range MeshAdapter::range() const {
  Range r;
  forEachFreeEdge([&](std::uint32_t a, std::uint32_t b) {
    const double l = length(a, b);
    r.outside += l > kSplitAbove || l < kCollapseBelow;
    r.longest = std::max(r.longest, l);
  });
  return r;
}

void MeshAdapter::splitLongEdges() {
  for (const Edge& e : edgesOutside(true)) {
    const std::uint32_t c = mesh_.findUndirectedEdge(e.a, e.b);
    if (c != kNone && mesh_.kind(c) == EdgeKind::Free) split(c);
  }
}

void MeshAdapter::split(std::uint32_t c) {
  const std::uint32_t x = mesh_.vertex(c), u = mesh_.vertex(nextCorner(c)),
                      w = mesh_.vertex(prevCorner(c)), y = mesh_.vertex(mesh_.neighbour(c));
  const Vec2 m = midpoint(mesh_.point(u), mesh_.point(w));
  const Vec2 px = mesh_.point(x), pu = mesh_.point(u), pw = mesh_.point(w), py = mesh_.point(y);
  // Rounding may put the midpoint off the edge: every new triangle must stay positive.
  if (orient2d(px, pu, m) <= 0 || orient2d(px, m, pw) <= 0 || orient2d(py, pw, m) <= 0 ||
      orient2d(py, m, pu) <= 0)
    return;
  const std::uint32_t v = mesh_.addPoint(m);
  target_.push_back(0);
  hint_.push_back(hint_[u]);
  mark_.push_back(0);
  touched_.push_back(0);
  updateSize(v);
  mesh_.split(c, v);
  for (std::uint32_t changed : {x, u, w, y, v}) touch(changed);
}

void MeshAdapter::collapseShortEdges() {
  for (const Edge& e : edgesOutside(false)) {
    if (!mesh_.inMesh(e.a) || !mesh_.inMesh(e.b) || mesh_.findUndirectedEdge(e.a, e.b) == kNone)
      continue;
    if (!tryCollapse(e.a, e.b)) tryCollapse(e.b, e.a);
  }
}

// Merges v into w if v may move, the result is a valid triangulation (the link condition:
// v and w have exactly two common neighbours; every triangle stays positive) and it makes
// no long edge nor a bad triangle.
bool MeshAdapter::tryCollapse(std::uint32_t v, std::uint32_t w) {
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
    if (orient2d(pw, pb, pa) <= 0 || length(w, b) > kSplitAbove) return false;
    newWorst = std::min(newWorst, quality(pw, pb, pa));
  }
  if (newWorst < std::min(oldWorst, kCollapseQuality)) return false;
  for (std::uint32_t c : ring_) touch(mesh_.vertex(nextCorner(c)));
  mesh_.collapse(v, w, ring_);
  return true;
}

// Lawson-style swaps for quality: an edge is swapped when the worse of its two triangles
// gets better. Each swap raises the sorted list of qualities, so the loop ends.
void MeshAdapter::swapEdges() {
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

bool MeshAdapter::swapImproves(std::uint32_t c) const {
  const std::uint32_t across = mesh_.neighbour(c);
  if (across == kNone || mesh_.kind(c) != EdgeKind::Free) return false;
  const Vec2 x = mesh_.point(mesh_.vertex(c)), u = mesh_.point(mesh_.vertex(nextCorner(c))),
             w = mesh_.point(mesh_.vertex(prevCorner(c))), y = mesh_.point(mesh_.vertex(across));
  const double before = std::min(quality(x, u, w), quality(y, w, u));
  const double after = std::min(quality(x, u, y), quality(y, w, x));
  // The exact test last: it only confirms what the qualities, 0 if not positive, suggest.
  return after > before * (1 + 1e-3) && orient2d(x, u, y) > 0 && orient2d(y, w, x) > 0;
}

void MeshAdapter::smoothVertices() {
  for (std::uint32_t v = firstMovable_; v < mesh_.pointCount(); ++v)
    if (mesh_.inMesh(v) && recent(v)) smoothVertex(v);
}

// Moves v towards the centroid of its neighbours, as far as keeps every triangle around it
// positive and the worst of them no worse.
void MeshAdapter::smoothVertex(std::uint32_t v) {
  if (!mesh_.ring(v, ring_)) return;
  double su = 0, sv = 0, worst = 1;
  for (std::uint32_t c : ring_) {
    const Vec2 p = mesh_.point(mesh_.vertex(nextCorner(c)));
    su += p.u, sv += p.v;
    worst = std::min(worst, quality(c / 3));
  }
  const Vec2 old = mesh_.point(v);
  const Vec2 centroid{su / ring_.size(), sv / ring_.size()};
  for (double step : {1.0, 0.5, 0.25}) {
    const Vec2 p{old.u + step * (centroid.u - old.u), old.v + step * (centroid.v - old.v)};
    if (worstAround(p, ring_) >= worst && allPositiveAround(p, ring_)) {
      mesh_.movePoint(v, p);
      updateSize(v);
      // Moves that no longer matter leave the neighbourhood settled.
      if (metricLength(old, p) > kSettled * target_[v]) {
        touch(v);
        for (std::uint32_t c : ring_) touch(mesh_.vertex(nextCorner(c)));
      }
      return;
    }
  }
}

// The worst quality of the triangles of `ring` with their common vertex at p.
double MeshAdapter::worstAround(Vec2 p, const std::vector<std::uint32_t>& ring) const {
  double worst = 1;
  for (std::uint32_t c : ring)
    worst = std::min(worst, quality(p, mesh_.point(mesh_.vertex(nextCorner(c))),
                                    mesh_.point(mesh_.vertex(prevCorner(c)))));
  return worst;
}

bool MeshAdapter::allPositiveAround(Vec2 p, const std::vector<std::uint32_t>& ring) const {
  for (std::uint32_t c : ring)
    if (orient2d(p, mesh_.point(mesh_.vertex(nextCorner(c))),
                 mesh_.point(mesh_.vertex(prevCorner(c)))) <= 0)
      return false;
  return true;
}

PlanarMesh MeshAdapter::run(int smoothingPasses) {
  // While edges more than twice too long remain, the mesh is still being refined and the
  // number of edges out of range grows; only then does it have to come down.
  std::size_t fewest = static_cast<std::size_t>(-1);
  for (int pass = 0, stalled = 0; pass < kMaxPasses; ++pass, ++pass_) {
    everywhere_ = pass == 0;
    splitLongEdges();
    collapseShortEdges();
    swapEdges();
    smoothVertices();
    swapEdges();
    const Range r = range();
    if (r.outside == 0) break;
    if (r.longest > 2 * kSplitAbove) continue;
    if (r.outside < fewest)
      fewest = r.outside, stalled = 0;
    else if (++stalled == kPassesWithoutProgress)
      break;
  }
  everywhere_ = true;
  for (int pass = 0; pass < smoothingPasses; ++pass) {
    smoothVertices();
    swapEdges();
  }
  return result();
}

PlanarMesh MeshAdapter::result() const {
  PlanarMesh out;
  out.points.reserve(mesh_.pointCount());
  for (std::uint32_t v = 0; v < mesh_.pointCount(); ++v) out.points.push_back(mesh_.point(v));
  out.sizes.assign(mesh_.sizes().begin(), mesh_.sizes().end());
  for (std::uint32_t t = 0; t < mesh_.triangleCount(); ++t)
    if (mesh_.alive(t))
      for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) out.triangles.push_back(mesh_.vertex(c));
  return out;
}

}  // namespace

PlanarMesh adaptMesh(const Triangulation2D& boundary, const std::vector<std::uint8_t>& inside,
                     std::uint32_t firstMovable, int smoothingPasses,
                     const SurfaceMetric* metric, const WorkPlaneSize* field) {
  return MeshAdapter(boundary, inside, firstMovable, metric, field).run(smoothingPasses);
}

}  // namespace geomesh
