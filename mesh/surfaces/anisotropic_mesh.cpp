// AnisotropicMesher: splits, collapses, swaps and smoothing until edges have unit metric length.
#include "mesh/surfaces/anisotropic_mesh.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "mesh/core/predicates.h"
#include "mesh/surfaces/anisotropic_gradation.h"
#include "mesh/surfaces/anisotropic_metric.h"

namespace geomesh {
namespace {

// Edges are split above sqrt 2 and collapsed below 1/sqrt 2 in the metric: halving a long
// edge never makes a collapsible one.
constexpr double kSplitAbove = 1.4142135623730951;
constexpr double kCollapseBelow = 0.7071067811865476;
constexpr int kMaxPasses = 40;
// The passes stop when this many in a row leave at least as many edges out of range.
constexpr int kPassesWithoutProgress = 3;
// Passes make progress when they bring the number of edges out of range below this fraction
// of the fewest so far.
constexpr double kProgress = 0.97;
// A collapse may lower the metric quality of the triangles around it down to this, no further.
constexpr double kCollapseQuality = 0.2;
// A vertex that smoothing moves by less than this metric length has settled, and a metric
// that gradation changes by less than this fraction has not changed.
constexpr double kSettled = 0.02;

constexpr auto nextCorner = Triangulation2D::nextCorner;
constexpr auto prevCorner = Triangulation2D::prevCorner;

Vec2 sub(Vec2 a, Vec2 b) {
  return {a.u - b.u, a.v - b.v};
}

// gamma (twice the inradius over the circumradius) of a triangle, 0 if it is not positive.
double gamma(Vec2 a, Vec2 b, Vec2 c) {
  const double area = 0.5 * ((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
  if (!(area > 0)) return 0;
  const auto len = [](Vec2 d) { return std::sqrt(d.u * d.u + d.v * d.v); };
  const double la = len(sub(c, b)), lb = len(sub(a, c)), lc = len(sub(b, a));
  return 16 * area * area / (la * lb * lc * (la + lb + lc));
}

// The length of an edge whose ends measure it la and lb, the metric varying geometrically
// between them (the logarithmic mean of the two).
double edgeLength(double la, double lb) {
  if (std::abs(la - lb) <= 1e-6 * (la + lb)) return 0.5 * (la + lb);
  return (la - lb) / std::log(la / lb);
}

Triangulation2D domainOf(const Triangulation2D& tri, const std::vector<std::uint8_t>& inside) {
  Triangulation2D domain = tri;
  domain.keepTriangles(inside);
  return domain;
}

struct Edge {
  double length;  // in the metric
  std::uint32_t a, b;
};

class AnisotropicMesher {
 public:
  AnisotropicMesher(const Triangulation2D& boundary, const std::vector<std::uint8_t>& inside,
                    std::uint32_t firstMovable, const SurfaceMetric* surface,
                    const WorkPlaneMetric* metric, const WorkPlaneSize* bound,
                    const AnisotropicSettings& settings);
  PlanarMesh run(int smoothingPasses);

 private:
  Metric2 surfaceAt(Vec2 p) const { return surface_ ? surface_->at(p) : Metric2{}; }
  Metric2 isotropicAt(Vec2 p, double h) const { return scaled(surfaceAt(p), 1 / (h * h)); }
  Metric2 ownMetric(std::uint32_t v) const;
  void addVertexData(std::uint32_t v);
  void refreshMetric(std::uint32_t v);
  void gradeAll();
  double length(std::uint32_t a, std::uint32_t b) const;
  double quality(Vec2 a, Vec2 b, Vec2 c, Metric2 m) const;
  double quality(std::uint32_t t) const;
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
  void swapEdges();
  bool swapImproves(std::uint32_t corner) const;
  void smoothVertices();
  void smoothVertex(std::uint32_t v);
  double worstAround(std::uint32_t v, Vec2 p, const std::vector<std::uint32_t>& ring) const;
  bool allPositiveAround(Vec2 p, const std::vector<std::uint32_t>& ring) const;
  PlanarMesh result() const;
  void touch(std::uint32_t v) { touched_[v] = pass_; }
  // Whether v changed, or a neighbour of v moved, in this pass or the previous one: the rest
  // of the mesh is as swaps and smoothing left it.
  bool recent(std::uint32_t v) const { return everywhere_ || touched_[v] + 1 >= pass_; }
  void touchRing(std::uint32_t v);

  Triangulation2D mesh_;  // the domain only
  const SurfaceMetric* surface_;
  const WorkPlaneMetric* metric_;
  const WorkPlaneSize* bound_;
  AnisotropicSettings settings_;
  std::uint32_t firstMovable_;
  double largest_ = 1;                // no size above this: the domain's extent
  std::vector<Metric2> own_;          // per vertex: the metric asked for there
  std::vector<Metric2> graded_;       // per vertex: own_ after gradation
  std::vector<std::uint32_t> mark_;   // per vertex: stamps of the link test
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> touched_;  // per vertex: the last pass that changed it
  std::uint32_t pass_ = 1;
  bool everywhere_ = true;  // swaps, smoothing and edge checks go over the whole mesh
  std::vector<std::uint32_t> ring_, otherRing_, offsets_, neighbours_;
};

AnisotropicMesher::AnisotropicMesher(const Triangulation2D& boundary,
                                     const std::vector<std::uint8_t>& inside,
                                     std::uint32_t firstMovable, const SurfaceMetric* surface,
                                     const WorkPlaneMetric* metric, const WorkPlaneSize* bound,
                                     const AnisotropicSettings& settings)
    : mesh_(domainOf(boundary, inside)), surface_(surface), metric_(metric), bound_(bound),
      settings_(settings), firstMovable_(firstMovable) {
  Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (std::uint32_t v = 0; v < mesh_.pointCount(); ++v) {
    if (!mesh_.inMesh(v)) continue;
    const Vec2 p = mesh_.point(v);
    lo = {std::min(lo.u, p.u), std::min(lo.v, p.v)};
    hi = {std::max(hi.u, p.u), std::max(hi.v, p.v)};
  }
  if (hi.u > lo.u || hi.v > lo.v) largest_ = std::hypot(hi.u - lo.u, hi.v - lo.v);
  for (std::uint32_t v = 0; v < mesh_.pointCount(); ++v) addVertexData(v);
}

// The metric at v before gradation: see anisotropicMesh.
Metric2 AnisotropicMesher::ownMetric(std::uint32_t v) const {
  const Vec2 p = mesh_.point(v);
  const Metric2 unbounded = isotropicAt(p, largest_);
  Metric2 m = metric_ ? (*metric_)(p) : unbounded;
  if (!isPositiveDefinite(m)) m = unbounded;
  // Without a metric, sizes grow inwards from the boundary's. With one, the boundary's
  // (realised by the 1D mesh, often at the metric's smallest size in every direction) would
  // spread that smallest size inwards: the metric alone rules there.
  const double h = mesh_.size(v);
  if (!metric_ && v < firstMovable_ && h > 0 && std::isfinite(h))
    m = intersect(m, isotropicAt(p, h));
  if (bound_) {
    const double b = (*bound_)(p);
    if (b > 0 && std::isfinite(b)) m = intersect(m, isotropicAt(p, b));
  }
  // Sizes and their ratio are bounded on the surface, in the frame of its own lengths.
  const MetricFrame frame(surfaceAt(p));
  const double largest = largest_;
  const Metric2 clamped = mapSizes(
      inFrame(m, frame), [largest](double size) { return std::min(size, largest); },
      settings_.anisoMax);
  return outOfFrame(clamped, frame);
}

void AnisotropicMesher::addVertexData(std::uint32_t v) {
  mark_.resize(v + 1, 0);
  touched_.resize(v + 1, 0);
  own_.resize(v + 1);
  graded_.resize(v + 1);
  if (mesh_.inMesh(v)) own_[v] = graded_[v] = ownMetric(v);
}

// v's metric after it moved or appeared: its own, lowered by its neighbours' grown to it.
void AnisotropicMesher::refreshMetric(std::uint32_t v) {
  own_[v] = graded_[v] = ownMetric(v);
  if (!(settings_.smoothRatio > 1) || !std::isfinite(settings_.smoothRatio)) return;
  const double rate = settings_.smoothRatio - 1;
  const bool closed = mesh_.ring(v, ring_);
  const auto lowerBy = [&](std::uint32_t w) {
    const Metric2 grown = grownAlong(graded_[w], sub(mesh_.point(v), mesh_.point(w)), rate);
    intersectInto(graded_[v], grown, 0);
  };
  for (std::uint32_t c : ring_) lowerBy(mesh_.vertex(nextCorner(c)));
  if (!closed && !ring_.empty()) lowerBy(mesh_.vertex(prevCorner(ring_.back())));
}

// Gradation over the whole mesh, from the vertices' own metrics.
void AnisotropicMesher::gradeAll() {
  const std::size_t n = mesh_.pointCount();
  offsets_.assign(n + 1, 0);
  const auto forEachEdge = [&](auto f) {
    for (std::uint32_t t = 0; t < mesh_.triangleCount(); ++t) {
      if (!mesh_.alive(t)) continue;
      for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c)
        if (mesh_.neighbour(c) == kNone || c < mesh_.neighbour(c))
          f(mesh_.vertex(nextCorner(c)), mesh_.vertex(prevCorner(c)));
    }
  };
  forEachEdge([&](std::uint32_t a, std::uint32_t b) { ++offsets_[a + 1], ++offsets_[b + 1]; });
  for (std::size_t v = 0; v < n; ++v) offsets_[v + 1] += offsets_[v];
  neighbours_.resize(offsets_[n]);
  std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
  forEachEdge([&](std::uint32_t a, std::uint32_t b) {
    neighbours_[fill[a]++] = b;
    neighbours_[fill[b]++] = a;
  });
  std::vector<Metric2> before = std::exchange(graded_, own_);
  gradeMetrics(mesh_.points(), {offsets_, neighbours_}, graded_, settings_.smoothRatio);
  for (std::uint32_t v = 0; v < n; ++v) {
    const Metric2 a = before[v], b = graded_[v];
    const double scale = std::abs(b.a) + std::abs(b.c);
    if (std::abs(a.a - b.a) + std::abs(a.b - b.b) + std::abs(a.c - b.c) > kSettled * scale)
      touch(v);
  }
}

// Marks v and its neighbours as changed.
void AnisotropicMesher::touchRing(std::uint32_t v) {
  touch(v);
  const bool closed = mesh_.ring(v, otherRing_);
  for (std::uint32_t c : otherRing_) touch(mesh_.vertex(nextCorner(c)));
  if (!closed && !otherRing_.empty()) touch(mesh_.vertex(prevCorner(otherRing_.back())));
}

double AnisotropicMesher::length(std::uint32_t a, std::uint32_t b) const {
  const Vec2 d = sub(mesh_.point(b), mesh_.point(a));
  return edgeLength(std::sqrt(lengthSquared(graded_[a], d)),
                    std::sqrt(lengthSquared(graded_[b], d)));
}

double AnisotropicMesher::quality(Vec2 a, Vec2 b, Vec2 c, Metric2 m) const {
  const MetricFrame f(m);
  return gamma(f.apply(a), f.apply(b), f.apply(c));
}

double AnisotropicMesher::quality(std::uint32_t t) const {
  const std::uint32_t a = mesh_.vertex(3 * t), b = mesh_.vertex(3 * t + 1),
                      c = mesh_.vertex(3 * t + 2);
  return quality(mesh_.point(a), mesh_.point(b), mesh_.point(c),
                 mean(graded_[a], graded_[b], graded_[c]));
}

// Calls f(a, b) for each free edge once.
template <class F>
void AnisotropicMesher::forEachFreeEdge(F f) const {
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
std::vector<Edge> AnisotropicMesher::edgesOutside(bool longOnes) const {
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

AnisotropicMesher::Range AnisotropicMesher::range() const {
  Range r;
  forEachFreeEdge([&](std::uint32_t a, std::uint32_t b) {
    const double l = length(a, b);
    r.outside += l > kSplitAbove || l < kCollapseBelow;
    r.longest = std::max(r.longest, l);
  });
  return r;
}

void AnisotropicMesher::splitLongEdges() {
  for (const Edge& e : edgesOutside(true)) {
    const std::uint32_t c = mesh_.findUndirectedEdge(e.a, e.b);
    if (c != kNone && mesh_.kind(c) == EdgeKind::Free) split(c);
  }
}

void AnisotropicMesher::split(std::uint32_t c) {
  const std::uint32_t x = mesh_.vertex(c), u = mesh_.vertex(nextCorner(c)),
                      w = mesh_.vertex(prevCorner(c)), y = mesh_.vertex(mesh_.neighbour(c));
  const Vec2 px = mesh_.point(x), pu = mesh_.point(u), pw = mesh_.point(w), py = mesh_.point(y);
  const Vec2 m{0.5 * (pu.u + pw.u), 0.5 * (pu.v + pw.v)};
  // Rounding may put the midpoint off the edge: every new triangle must stay positive.
  if (orient2d(px, pu, m) <= 0 || orient2d(px, m, pw) <= 0 || orient2d(py, pw, m) <= 0 ||
      orient2d(py, m, pu) <= 0)
    return;
  const std::uint32_t v = mesh_.addPoint(m);
  mesh_.split(c, v);
  addVertexData(v);
  refreshMetric(v);
  for (std::uint32_t changed : {x, u, w, y, v}) touch(changed);
}

void AnisotropicMesher::collapseShortEdges() {
  for (const Edge& e : edgesOutside(false)) {
    if (!mesh_.inMesh(e.a) || !mesh_.inMesh(e.b) || mesh_.findUndirectedEdge(e.a, e.b) == kNone)
      continue;
    if (!tryCollapse(e.a, e.b)) tryCollapse(e.b, e.a);
  }
}

// Merges v into w if v may move, the result is a valid triangulation (the link condition:
// v and w have exactly two common neighbours; every triangle stays positive) and it makes
// no long edge nor a bad triangle.
bool AnisotropicMesher::tryCollapse(std::uint32_t v, std::uint32_t w) {
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
    newWorst = std::min(newWorst, quality(pw, pb, pa, mean(graded_[w], graded_[b], graded_[a])));
  }
  if (newWorst < std::min(oldWorst, kCollapseQuality)) return false;
  for (std::uint32_t c : ring_) touch(mesh_.vertex(nextCorner(c)));
  mesh_.collapse(v, w, ring_);
  return true;
}

// Swaps for metric quality: an edge is swapped when the worse of its two triangles gets
// better. Each swap raises the sorted list of qualities, so the loop ends.
void AnisotropicMesher::swapEdges() {
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

bool AnisotropicMesher::swapImproves(std::uint32_t c) const {
  const std::uint32_t across = mesh_.neighbour(c);
  if (across == kNone || mesh_.kind(c) != EdgeKind::Free) return false;
  const std::uint32_t ix = mesh_.vertex(c), iu = mesh_.vertex(nextCorner(c)),
                      iw = mesh_.vertex(prevCorner(c)), iy = mesh_.vertex(across);
  const Vec2 x = mesh_.point(ix), u = mesh_.point(iu), w = mesh_.point(iw), y = mesh_.point(iy);
  const Metric2 mx = graded_[ix], mu = graded_[iu], mw = graded_[iw], my = graded_[iy];
  const double before = std::min(quality(x, u, w, mean(mx, mu, mw)),
                                 quality(y, w, u, mean(my, mw, mu)));
  const double after = std::min(quality(x, u, y, mean(mx, mu, my)),
                                quality(y, w, x, mean(my, mw, mx)));
  // The exact test last: it only confirms what the qualities, 0 if not positive, suggest.
  return after > before * (1 + 1e-3) && orient2d(x, u, y) > 0 && orient2d(y, w, x) > 0;
}

void AnisotropicMesher::smoothVertices() {
  for (std::uint32_t v = firstMovable_; v < mesh_.pointCount(); ++v)
    if (mesh_.inMesh(v) && recent(v)) smoothVertex(v);
}

// Moves v towards the mean of the places that would put it at unit metric length from each
// neighbour (along the present edge), as far as keeps every triangle around it positive
// and the worst of them no worse.
void AnisotropicMesher::smoothVertex(std::uint32_t v) {
  if (!mesh_.ring(v, ring_)) return;
  const Vec2 old = mesh_.point(v);
  double su = 0, sv = 0, worst = 1;
  for (std::uint32_t c : ring_) {
    const std::uint32_t w = mesh_.vertex(nextCorner(c));
    const double l = length(v, w);
    if (!(l > 0)) return;
    const Vec2 p = mesh_.point(w), d = sub(old, p);
    su += p.u + d.u / l, sv += p.v + d.v / l;
    worst = std::min(worst, quality(c / 3));
  }
  const Vec2 target{su / ring_.size(), sv / ring_.size()};
  for (double step : {1.0, 0.5, 0.25}) {
    const Vec2 p{old.u + step * (target.u - old.u), old.v + step * (target.v - old.v)};
    if (worstAround(v, p, ring_) >= worst && allPositiveAround(p, ring_)) {
      mesh_.movePoint(v, p);
      // Moves that no longer matter leave the neighbourhood settled.
      if (std::sqrt(lengthSquared(graded_[v], sub(p, old))) > kSettled) touchRing(v);
      refreshMetric(v);
      return;
    }
  }
}

// The worst quality of the triangles of `ring` with their common vertex v at p.
double AnisotropicMesher::worstAround(std::uint32_t v, Vec2 p,
                                      const std::vector<std::uint32_t>& ring) const {
  double worst = 1;
  for (std::uint32_t c : ring) {
    const std::uint32_t b = mesh_.vertex(nextCorner(c)), a = mesh_.vertex(prevCorner(c));
    worst = std::min(worst, quality(p, mesh_.point(b), mesh_.point(a),
                                    mean(graded_[v], graded_[b], graded_[a])));
  }
  return worst;
}

bool AnisotropicMesher::allPositiveAround(Vec2 p, const std::vector<std::uint32_t>& ring) const {
  for (std::uint32_t c : ring)
    if (orient2d(p, mesh_.point(mesh_.vertex(nextCorner(c))),
                 mesh_.point(mesh_.vertex(prevCorner(c)))) <= 0)
      return false;
  return true;
}

PlanarMesh AnisotropicMesher::run(int smoothingPasses) {
  // While edges more than twice too long remain and the longest keeps shrinking, the mesh is
  // still being refined and the number of edges out of range grows; then it has to come down.
  // (Long edges may remain for good next to boundary edges far longer than the metric asks.)
  std::size_t fewest = static_cast<std::size_t>(-1);
  double previousLongest = 1e300;
  gradeAll();
  for (int pass = 0, stalled = 0; pass < kMaxPasses; ++pass, ++pass_) {
    everywhere_ = pass == 0;
    splitLongEdges();
    collapseShortEdges();
    swapEdges();
    smoothVertices();
    swapEdges();
    gradeAll();
    const Range r = range();
    if (r.outside == 0) break;
    const bool refining = r.longest > 2 * kSplitAbove && r.longest < 0.9 * previousLongest;
    previousLongest = r.longest;
    if (refining) continue;
    if (r.outside < kProgress * static_cast<double>(fewest))
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

PlanarMesh AnisotropicMesher::result() const {
  PlanarMesh out;
  out.points.reserve(mesh_.pointCount());
  out.sizes.reserve(mesh_.pointCount());
  for (std::uint32_t v = 0; v < mesh_.pointCount(); ++v) {
    const Vec2 p = mesh_.point(v);
    out.points.push_back(p);
    // The smallest size the metric asks for on the surface.
    const double large = eigen(inFrame(graded_[v], MetricFrame(surfaceAt(p)))).large;
    out.sizes.push_back(mesh_.inMesh(v) && large > 0 ? 1 / std::sqrt(large) : mesh_.size(v));
  }
  for (std::uint32_t t = 0; t < mesh_.triangleCount(); ++t)
    if (mesh_.alive(t))
      for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) out.triangles.push_back(mesh_.vertex(c));
  return out;
}

}  // namespace

PlanarMesh anisotropicMesh(const Triangulation2D& boundary, const std::vector<std::uint8_t>& inside,
                           std::uint32_t firstMovable, int smoothingPasses,
                           const SurfaceMetric* surface, const WorkPlaneMetric* metric,
                           const WorkPlaneSize* bound, const AnisotropicSettings& settings) {
  return AnisotropicMesher(boundary, inside, firstMovable, surface, metric, bound, settings)
      .run(smoothingPasses);
}

}  // namespace geomesh
