// AnisotropicMesher: splits, collapses, swaps and smoothing until edges have unit metric length.
#include "mesh/surfaces/anisotropic_mesh.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mesh/surfaces/anisotropic_gradation.h"
#include "mesh/surfaces/anisotropic_metric.h"
#include "mesh/surfaces/local_remeshing.h"

namespace geomesh {
namespace {

// Edges are split above sqrt 2 and collapsed below 1/sqrt 2 in the metric: halving a long
// edge never makes a collapsible one.
constexpr double kSplitAbove = 1.4142135623730951;
constexpr double kCollapseBelow = 0.7071067811865476;
// Passes make progress when they bring the number of edges out of range below this fraction
// of the fewest so far.
constexpr double kProgress = 0.97;
// A vertex that smoothing moves by less than this metric length has settled, and a metric
// that gradation changes by less than this fraction has not changed.
constexpr double kSettled = 0.02;

Vec2 sub(Vec2 a, Vec2 b) {
  return {a.u - b.u, a.v - b.v};
}

// Lengths in the metric (varying geometrically along the edge), gamma qualities in the mean
// metric of a triangle's vertices, smoothing towards unit lengths, metrics graded between
// passes.
class AnisotropicMesher : public LocalRemesher<AnisotropicMesher> {
 public:
  AnisotropicMesher(const Triangulation2D& boundary, const std::vector<std::uint8_t>& inside,
                    std::uint32_t firstMovable, const SurfaceMetric* surface,
                    const WorkPlaneMetric* metric, const WorkPlaneSize* bound,
                    const AnisotropicSettings& settings);
  PlanarMesh run(int smoothingPasses);

 private:
  friend class LocalRemesher<AnisotropicMesher>;
  Metric2 surfaceAt(Vec2 p) const { return surface_ ? surface_->at(p) : Metric2{}; }
  Metric2 isotropicAt(Vec2 p, double h) const { return scaled(surfaceAt(p), 1 / (h * h)); }
  Metric2 ownMetric(std::uint32_t v) const;
  void addVertexData(std::uint32_t v);
  void refreshMetric(std::uint32_t v);
  void gradeAll();
  double length(std::uint32_t a, std::uint32_t b) const;
  double quality(std::uint32_t a, std::uint32_t b, std::uint32_t c, Vec2 pa, Vec2 pb,
                 Vec2 pc) const;
  std::uint32_t insertSplitVertex(std::uint32_t corner, Vec2 m);
  bool smoothingPlace(std::uint32_t v, std::uint32_t w, Vec2& place) const;
  void afterSmoothing(std::uint32_t v, Vec2 old, Vec2 p);
  PlanarMesh result() const;
  void touchRing(std::uint32_t v);

  const SurfaceMetric* surface_;
  const WorkPlaneMetric* metric_;
  const WorkPlaneSize* bound_;
  AnisotropicSettings settings_;
  double largest_ = 1;           // no size above this: the domain's extent
  std::vector<Metric2> own_;     // per vertex: the metric asked for there
  std::vector<Metric2> graded_;  // per vertex: own_ after gradation
  std::vector<std::uint32_t> offsets_, neighbours_;
};

AnisotropicMesher::AnisotropicMesher(const Triangulation2D& boundary,
                                     const std::vector<std::uint8_t>& inside,
                                     std::uint32_t firstMovable, const SurfaceMetric* surface,
                                     const WorkPlaneMetric* metric, const WorkPlaneSize* bound,
                                     const AnisotropicSettings& settings)
    : LocalRemesher(domainOf(boundary, inside), firstMovable, kSplitAbove, kCollapseBelow),
      surface_(surface),
      metric_(metric),
      bound_(bound),
      settings_(settings) {
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
  growVertexData(v + 1);
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

// The logarithmic mean of the lengths the two ends' metrics give the edge.
double AnisotropicMesher::length(std::uint32_t a, std::uint32_t b) const {
  const Vec2 d = sub(mesh_.point(b), mesh_.point(a));
  return logarithmicMean(std::sqrt(lengthSquared(graded_[b], d)),
                         std::sqrt(lengthSquared(graded_[a], d)));
}

double AnisotropicMesher::quality(std::uint32_t a, std::uint32_t b, std::uint32_t c, Vec2 pa,
                                  Vec2 pb, Vec2 pc) const {
  const MetricFrame f(mean(graded_[a], graded_[b], graded_[c]));
  return planarGamma(f.apply(pa), f.apply(pb), f.apply(pc));
}

// The metric of the new vertex is refreshed once it is linked to its neighbours.
std::uint32_t AnisotropicMesher::insertSplitVertex(std::uint32_t corner, Vec2 m) {
  const std::uint32_t v = mesh_.addPoint(m);
  mesh_.split(corner, v);
  addVertexData(v);
  refreshMetric(v);
  return v;
}

// The place at unit metric length from w along the present edge.
bool AnisotropicMesher::smoothingPlace(std::uint32_t v, std::uint32_t w, Vec2& place) const {
  const double l = length(v, w);
  if (!(l > 0)) return false;
  const Vec2 p = mesh_.point(w), d = sub(mesh_.point(v), p);
  place = {p.u + d.u / l, p.v + d.v / l};
  return true;
}

void AnisotropicMesher::afterSmoothing(std::uint32_t v, Vec2 old, Vec2 p) {
  // Moves that no longer matter leave the neighbourhood settled.
  if (std::sqrt(lengthSquared(graded_[v], sub(p, old))) > kSettled) touchRing(v);
  refreshMetric(v);
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
    modifyOnce();
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
  smoothAll(smoothingPasses);
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
  appendTriangles(out);
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
