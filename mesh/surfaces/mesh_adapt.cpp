// MeshAdapter: passes of edge splits, collapses, swaps and smoothing until edges fit the size.
#include "mesh/surfaces/mesh_adapt.h"

#include <algorithm>
#include <cmath>

#include "mesh/surfaces/local_remeshing.h"

namespace geomesh {
namespace {

// An edge is split above this length and collapsed below that one, in target sizes. With a
// ratio of 2 between them, halving a long edge never makes a collapsible one.
constexpr double kSplitAbove = 1.4;
constexpr double kCollapseBelow = 0.7;
// A vertex that smoothing moves by less than this fraction of the target size has settled.
constexpr double kSettled = 0.02;

Vec2 midpoint(Vec2 a, Vec2 b) {
  return {0.5 * (a.u + b.u), 0.5 * (a.v + b.v)};
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

// Lengths in target sizes (1 / the mean of 1 / h along the edge, the size varying linearly
// between its ends), gamma qualities, smoothing towards the centroid of the neighbours.
class MeshAdapter : public LocalRemesher<MeshAdapter> {
 public:
  MeshAdapter(const Triangulation2D& boundary, const std::vector<std::uint8_t>& inside,
              std::uint32_t firstMovable, const SurfaceMetric* metric, const WorkPlaneSize* field)
      : LocalRemesher(domainOf(boundary, inside), firstMovable, kSplitAbove, kCollapseBelow),
        background_(boundary, inside),
        metric_(metric),
        field_(field),
        target_(boundary.pointCount()),
        hint_(boundary.pointCount(), kNone) {
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
  friend class LocalRemesher<MeshAdapter>;
  double metricLength(Vec2 a, Vec2 b) const;
  double length(std::uint32_t a, std::uint32_t b) const {
    return metricLength(mesh_.point(a), mesh_.point(b)) / logarithmicMean(target_[a], target_[b]);
  }
  double quality(Vec2 a, Vec2 b, Vec2 c) const;
  double quality(std::uint32_t, std::uint32_t, std::uint32_t, Vec2 a, Vec2 b, Vec2 c) const {
    return quality(a, b, c);
  }
  std::uint32_t insertSplitVertex(std::uint32_t corner, Vec2 m);
  bool smoothingPlace(std::uint32_t, std::uint32_t w, Vec2& place) const {
    place = mesh_.point(w);
    return true;
  }
  void afterSmoothing(std::uint32_t v, Vec2 old, Vec2 p);
  void updateSize(std::uint32_t v);
  double cappedByField(double size, Vec2 x) const;
  PlanarMesh result() const;

  BoundarySizes background_;
  const SurfaceMetric* metric_;
  const WorkPlaneSize* field_;
  std::vector<double> target_;       // per vertex: the size asked for (field included)
  std::vector<std::uint32_t> hint_;  // per vertex: where its size was found in background_
};

double MeshAdapter::metricLength(Vec2 a, Vec2 b) const {
  const double du = b.u - a.u, dv = b.v - a.v;
  if (!metric_) return std::sqrt(du * du + dv * dv);
  const Metric2 m = metric_->at(midpoint(a, b));
  return std::sqrt(std::max(m.a * du * du + 2 * m.b * du * dv + m.c * dv * dv, 0.0));
}

double MeshAdapter::quality(Vec2 a, Vec2 b, Vec2 c) const {
  if (!metric_) return planarGamma(a, b, c);
  const MetricFrame f(metric_->at({(a.u + b.u + c.u) / 3, (a.v + b.v + c.v) / 3}));
  return planarGamma(f.apply(a), f.apply(b), f.apply(c));
}

// The new vertex takes its size where it lies in the background.
std::uint32_t MeshAdapter::insertSplitVertex(std::uint32_t corner, Vec2 m) {
  const std::uint32_t u = mesh_.vertex(nextCorner(corner));
  const std::uint32_t v = mesh_.addPoint(m);
  target_.push_back(0);
  hint_.push_back(hint_[u]);
  growVertexData(v + 1);
  updateSize(v);
  mesh_.split(corner, v);
  return v;
}

void MeshAdapter::afterSmoothing(std::uint32_t v, Vec2 old, Vec2 p) {
  updateSize(v);
  // Moves that no longer matter leave the neighbourhood settled.
  if (metricLength(old, p) > kSettled * target_[v]) {
    touch(v);
    for (std::uint32_t c : ring_) touch(mesh_.vertex(nextCorner(c)));
  }
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

PlanarMesh MeshAdapter::run(int smoothingPasses) {
  // While edges more than twice too long remain, the mesh is still being refined and the
  // number of edges out of range grows; only then does it have to come down.
  std::size_t fewest = static_cast<std::size_t>(-1);
  for (int pass = 0, stalled = 0; pass < kMaxPasses; ++pass, ++pass_) {
    everywhere_ = pass == 0;
    modifyOnce();
    const Range r = range();
    if (r.outside == 0) break;
    if (r.longest > 2 * kSplitAbove) continue;
    if (r.outside < fewest)
      fewest = r.outside, stalled = 0;
    else if (++stalled == kPassesWithoutProgress)
      break;
  }
  smoothAll(smoothingPasses);
  return result();
}

PlanarMesh MeshAdapter::result() const {
  PlanarMesh out;
  out.points.reserve(mesh_.pointCount());
  for (std::uint32_t v = 0; v < mesh_.pointCount(); ++v) out.points.push_back(mesh_.point(v));
  out.sizes.assign(mesh_.sizes().begin(), mesh_.sizes().end());
  appendTriangles(out);
  return out;
}

}  // namespace

PlanarMesh adaptMesh(const Triangulation2D& boundary, const std::vector<std::uint8_t>& inside,
                     std::uint32_t firstMovable, int smoothingPasses, const SurfaceMetric* metric,
                     const WorkPlaneSize* field) {
  return MeshAdapter(boundary, inside, firstMovable, metric, field).run(smoothingPasses);
}

}  // namespace geomesh
