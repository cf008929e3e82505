// FrontalRefiner: frontal-Delaunay, its quadrangle variant, and Delaunay refinement.
#include "mesh/surfaces/frontal_refinement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <tuple>
#include <utility>

#include "mesh/core/predicates.h"

namespace geomesh {
namespace {

// A triangle is good once its circumradius is below this multiple of the circumradius of the
// equilateral triangle of the target size.
constexpr double kAcceptRatio = 1.2;
// A new point closer than this fraction of the target size to a vertex is not inserted...
constexpr double kMinSpacing = 0.35;
// ... nor one closer to a boundary edge than this fraction of the edge's length (which would
// make a sliver against it; the reference refuses points about as close to a boundary edge).
constexpr double kEdgeSpacing = 0.2;
// The front does not step to a point where the field asks for sizes this many times smaller
// than the edge it builds on: a zone of much smaller sizes that no boundary node lies in is
// met by the front at its rim and left as it is (the reference's frontal mesher behaves so;
// its Delaunay refinement fills such zones).
constexpr double kLargestStepDown = 3.5;
constexpr double kSqrt3 = 1.7320508075688772;
constexpr double kSqrt2 = 1.4142135623730951;
constexpr double kPi = 3.14159265358979323846;

constexpr auto nextCorner = Triangulation2D::nextCorner;
constexpr auto prevCorner = Triangulation2D::prevCorner;

enum class State : std::uint8_t { Outside, Waiting, Active, Accepted };
// Where new points go: in front of the front (frontal-Delaunay), at the circumcentre of the
// worst triangle (Delaunay refinement), wherever it is, or in front of the front at the
// corner of a square cell aligned with a cross field (frontal-Delaunay for quadrangles).
enum class Placement : std::uint8_t { Frontal, Circumcenter, FrontalQuads };

struct HeapEntry {
  float ratio;
  std::uint32_t triangle;
  std::uint32_t stamp;
  friend bool operator<(const HeapEntry& a, const HeapEntry& b) {
    if (a.ratio != b.ratio) return a.ratio < b.ratio;
    return a.triangle > b.triangle;  // deterministic tie-break
  }
};

Vec2 sub(Vec2 a, Vec2 b) {
  return {a.u - b.u, a.v - b.v};
}
double length(Vec2 a) {
  return std::sqrt(a.u * a.u + a.v * a.v);
}

Vec2 circumcenter(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 ab = sub(b, a), ac = sub(c, a);
  const double d = 2 * (ab.u * ac.v - ab.v * ac.u);
  const double ab2 = ab.u * ab.u + ab.v * ab.v, ac2 = ac.u * ac.u + ac.v * ac.v;
  return {a.u + (ac.v * ab2 - ab.v * ac2) / d, a.v + (ab.u * ac2 - ac.u * ab2) / d};
}

class FrontalRefiner {
 public:
  FrontalRefiner(Triangulation2D& tri, std::vector<std::uint8_t>& inside,
                 const SurfaceMetric* metric, const WorkPlaneSize* field,
                 const WorkPlaneSize* bound, Placement placement)
      : tri_(tri), inside_(inside), metric_(metric), field_(field), bound_(bound),
        placement_(placement),
        idealRadius_(placement == Placement::FrontalQuads ? 1 / kSqrt2 : 1 / kSqrt3) {}

  void run() {
    const std::uint32_t firstNew = static_cast<std::uint32_t>(tri_.pointCount());
    const std::uint32_t n = static_cast<std::uint32_t>(tri_.triangleCount());
    state_.assign(n, State::Outside);
    stamp_.assign(n, 0);
    if (placement_ == Placement::FrontalQuads) initCrossField();
    for (std::uint32_t t = 0; t < n; ++t)
      if (inside_[t]) state_[t] = isGood(t) ? State::Accepted : State::Waiting;
    for (std::uint32_t t = 0; t < n; ++t) activateIfOnFront(t);
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end());
      const HeapEntry e = heap_.back();
      heap_.pop_back();
      if (stamp_[e.triangle] != e.stamp || state_[e.triangle] != State::Active) continue;
      if (!advanceFront(e.triangle)) state_[e.triangle] = State::Accepted;
    }
    if (field_ || bound_)
      for (std::uint32_t v = firstNew; v < tri_.pointCount(); ++v) {
        const double size = field_ ? std::min(tri_.size(v), fieldAt(v)) : tri_.size(v);
        tri_.setSize(v, boundedAt(size, tri_.point(v)));
      }
  }

 private:
  Vec2 p(std::uint32_t t, int i) const { return tri_.point(tri_.vertex(3 * t + i)); }
  // The field's size at vertex v, evaluated once.
  double fieldAt(std::uint32_t v) const {
    if (v >= fieldSizes_.size()) fieldSizes_.resize(tri_.pointCount(), -1);
    if (fieldSizes_[v] < 0) fieldSizes_[v] = (*field_)(tri_.point(v));
    return fieldSizes_[v];
  }
  // The smaller of the means, over the vertices, of the extended sizes and of the field's:
  // the field is seen at vertices only, so a zone of small sizes no vertex falls in is only
  // refined once a point lands there (as the reference does).
  double meanSize(std::span<const std::uint32_t> vertices) const {
    double extended = 0, field = 0;
    for (std::uint32_t v : vertices) {
      extended += tri_.size(v);
      if (field_) field += fieldAt(v);
    }
    return (field_ ? std::min(extended, field) : extended) / static_cast<double>(vertices.size());
  }
  double boundedAt(double size, Vec2 x) const {
    return bound_ ? std::min(size, (*bound_)(x)) : size;
  }
  Vec2 middle(std::uint32_t a, std::uint32_t b) const {
    return {0.5 * (tri_.point(a).u + tri_.point(b).u), 0.5 * (tri_.point(a).v + tri_.point(b).v)};
  }
  double targetSize(std::uint32_t t) const {
    const std::array<std::uint32_t, 3> v{tri_.vertex(3 * t), tri_.vertex(3 * t + 1),
                                         tri_.vertex(3 * t + 2)};
    return bound_ ? std::min(meanSize(v), (*bound_)(centroid(t))) : meanSize(v);
  }
  // Lengths near x on the surface are Euclidean lengths after this map.
  MetricFrame frameAt(Vec2 x) const {
    return metric_ ? MetricFrame(metric_->at(x)) : MetricFrame();
  }
  Vec2 centroid(std::uint32_t t) const {
    const Vec2 a = p(t, 0), b = p(t, 1), c = p(t, 2);
    return {(a.u + b.u + c.u) / 3, (a.v + b.v + c.v) / 3};
  }

  double ratio(std::uint32_t t) const {
    Vec2 a = p(t, 0), b = p(t, 1), c = p(t, 2);
    if (metric_) {
      const MetricFrame f = frameAt(centroid(t));
      a = f.apply(a), b = f.apply(b), c = f.apply(c);
    }
    const double area2 = std::abs((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
    const double radius = length(sub(b, a)) * length(sub(c, b)) * length(sub(a, c)) / (2 * area2);
    return radius / (idealRadius_ * targetSize(t));
  }
  bool isGood(std::uint32_t t) const { return ratio(t) < kAcceptRatio; }

  bool isFrontEdge(std::uint32_t corner) const {
    if (tri_.kind(corner) != EdgeKind::Free) return true;
    const std::uint32_t across = tri_.neighbour(corner);
    return across != kNone && state_[across / 3] == State::Accepted;
  }

  void activateIfOnFront(std::uint32_t t) {
    if (state_[t] != State::Waiting) return;
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
      if (placement_ == Placement::Circumcenter || isFrontEdge(c)) {
        state_[t] = State::Active;
        heap_.push_back({static_cast<float>(ratio(t)), t, stamp_[t]});
        std::push_heap(heap_.begin(), heap_.end());
        return;
      }
    }
  }

  // The front edge of t best suited to build on: the shortest one.
  std::uint32_t frontCorner(std::uint32_t t) const {
    std::uint32_t best = kNone;
    double bestLength = 0;
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
      if (!isFrontEdge(c)) continue;
      const double l = length(sub(tri_.point(tri_.vertex(prevCorner(c))),
                                  tri_.point(tri_.vertex(nextCorner(c)))));
      if (best == kNone || l < bestLength) best = c, bestLength = l;
    }
    return best;
  }

  // Where to put the new point in front of the edge of `corner` (Rebay's placement), in the
  // metric of the edge's midpoint.
  Vec2 frontPoint(std::uint32_t t, std::uint32_t corner) const {
    const std::uint32_t va = tri_.vertex(nextCorner(corner));
    const std::uint32_t vb = tri_.vertex(prevCorner(corner));
    const Vec2 edgeMiddle = middle(va, vb);
    const MetricFrame f = frameAt(edgeMiddle);
    const Vec2 a = f.apply(tri_.point(va)), b = f.apply(tri_.point(vb));
    const Vec2 mid{0.5 * (a.u + b.u), 0.5 * (a.v + b.v)};
    const Vec2 ab = sub(b, a);
    const double half = 0.5 * length(ab);
    const Vec2 inward{-ab.v / (2 * half), ab.u / (2 * half)};
    const Vec2 center = circumcenter(f.apply(p(t, 0)), f.apply(p(t, 1)), f.apply(p(t, 2)));
    const double q = std::max(length(sub(center, mid)), 1e-300);
    const std::array<std::uint32_t, 2> ends{va, vb};
    const double target = boundedAt(meanSize(ends), edgeMiddle) / kSqrt3;
    const double rho = std::min(std::max(target, half), (half * half + q * q) / (2 * q));
    const double d = rho + std::sqrt(std::max(rho * rho - half * half, 0.0));
    return f.invert({mid.u + d * inward.u, mid.v + d * inward.v});
  }

  // The barycentric coordinates of x in triangle t.
  std::array<double, 3> weights(std::uint32_t t, Vec2 x) const {
    const Vec2 a = p(t, 0), b = p(t, 1), c = p(t, 2);
    const double det = (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
    const double l1 = ((x.u - a.u) * (c.v - a.v) - (x.v - a.v) * (c.u - a.u)) / det;
    const double l2 = ((b.u - a.u) * (x.v - a.v) - (b.v - a.v) * (x.u - a.u)) / det;
    return {1 - l1 - l2, l1, l2};
  }
  // Size at x interpolated linearly in triangle t.
  double interpolatedSize(std::uint32_t t, Vec2 x) const {
    const std::array<double, 3> w = weights(t, x);
    return w[0] * tri_.size(tri_.vertex(3 * t)) + w[1] * tri_.size(tri_.vertex(3 * t + 1)) +
           w[2] * tri_.size(tri_.vertex(3 * t + 2));
  }

  // The cross field of quadrangle meshing: at each vertex, (cos 4a, sin 4a) for the angle a
  // of the square cells wanted there, summed over the constrained edges at boundary
  // vertices (a cross is the same turned by a quarter turn) and interpolated inside.
  void initCrossField() {
    cross_.assign(tri_.pointCount(), {0, 0});
    for (std::uint32_t t = 0; t < tri_.triangleCount(); ++t) {
      if (!inside_[t]) continue;
      for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
        if (tri_.kind(c) == EdgeKind::Free) continue;
        const std::uint32_t va = tri_.vertex(nextCorner(c));
        const std::uint32_t vb = tri_.vertex(prevCorner(c));
        const Vec2 pa = tri_.point(va), pb = tri_.point(vb);
        const Vec2 d = frameAt({0.5 * (pa.u + pb.u), 0.5 * (pa.v + pb.v)}).apply(sub(pb, pa));
        const double angle = 4 * std::atan2(d.v, d.u);
        for (std::uint32_t v : {va, vb})
          cross_[v] = {cross_[v].u + std::cos(angle), cross_[v].v + std::sin(angle)};
      }
    }
  }
  Vec2 interpolatedCross(std::uint32_t t, Vec2 x) const {
    const std::array<double, 3> w = weights(t, x);
    Vec2 sum{0, 0};
    for (int i = 0; i < 3; ++i) {
      const Vec2 c = cross_[tri_.vertex(3 * t + i)];
      sum = {sum.u + w[i] * c.u, sum.v + w[i] * c.v};
    }
    return sum;
  }

  // Where to put the new point in front of the edge of `corner` for square cells: at a
  // target size from one end of the edge along the cross direction closest to the edge's
  // inward normal, the candidate whose distances to both ends, in the cross's max-norm, are
  // nearest the target size (an axis edge gets a right angle at its end, a diagonal one its
  // opposite corner). Rebay's point when that one would not replace t.
  Vec2 quadPoint(std::uint32_t t, std::uint32_t corner) const {
    const std::uint32_t va = tri_.vertex(nextCorner(corner));
    const std::uint32_t vb = tri_.vertex(prevCorner(corner));
    const Vec2 mid = middle(va, vb);
    const MetricFrame f = frameAt(mid);
    const Vec2 a = f.apply(tri_.point(va)), b = f.apply(tri_.point(vb));
    const Vec2 ab = sub(b, a);
    const Vec2 inward{-ab.v / length(ab), ab.u / length(ab)};
    const Vec2 cross{cross_[va].u + cross_[vb].u, cross_[va].v + cross_[vb].v};
    const double angle = cross.u == 0 && cross.v == 0 ? std::atan2(ab.v, ab.u)
                                                      : std::atan2(cross.v, cross.u) / 4;
    const std::array<std::uint32_t, 2> ends{va, vb};
    const double target = boundedAt(meanSize(ends), mid);
    const auto maxNorm = [angle](Vec2 d) {
      const double c = std::cos(angle), s = std::sin(angle);
      return std::max(std::abs(c * d.u + s * d.v), std::abs(-s * d.u + c * d.v));
    };
    Vec2 best{};
    double bestScore = 1e300;
    for (const Vec2 base : {a, b})
      for (int k = 0; k < 4; ++k) {
        const Vec2 d{std::cos(angle + k * kPi / 2), std::sin(angle + k * kPi / 2)};
        if (d.u * inward.u + d.v * inward.v < 0.5) continue;
        const Vec2 x{base.u + target * d.u, base.v + target * d.v};
        const double score =
            std::abs(maxNorm(sub(x, a)) - target) + std::abs(maxNorm(sub(x, b)) - target);
        // Rounding must not decide between equally good candidates: the first one stays.
        if (score < bestScore - 1e-9 * target) best = x, bestScore = score;
      }
    const Vec2 x = f.invert(best);
    if (bestScore == 1e300 || incircle(p(t, 0), p(t, 1), p(t, 2), x) <= 0)
      return frontPoint(t, corner);
    return x;
  }

  // The cavity of new vertex v at x: in the surface's metric at x when there is one (falling
  // back to the plain one if that is not star-shaped).
  bool findCavity(std::uint32_t v, std::uint32_t found, Vec2 x) {
    using Status = Triangulation2D::InsertStatus;
    if (metric_) {
      const MetricFrame f = frameAt(x);
      if (tri_.findCavity(v, found, &f) == Status::Inserted) return true;
    }
    return tri_.findCavity(v, found) == Status::Inserted;
  }

  // True if x would come closer than kMinSpacing target sizes to one of its future
  // neighbours, or closer than kEdgeSpacing lengths of a boundary edge of its cavity to it.
  bool tooClose(std::span<const Triangulation2D::CavityEdge> cavity, Vec2 x, double size) const {
    const MetricFrame f = frameAt(x);
    const double limit = kMinSpacing * size;
    for (const Triangulation2D::CavityEdge& e : cavity) {
      const Vec2 a = f.apply(sub(tri_.point(e.a), x));
      if (length(a) < limit) return true;
      if (e.kind == EdgeKind::Free) continue;
      const Vec2 ab = sub(f.apply(sub(tri_.point(e.b), x)), a);
      const double t = -(a.u * ab.u + a.v * ab.v) / (ab.u * ab.u + ab.v * ab.v);
      if (t > 0 && t < 1 && length({a.u + t * ab.u, a.v + t * ab.v}) < kEdgeSpacing * length(ab))
        return true;
    }
    return false;
  }

  // The circumcentre of t in the metric at its centroid, or its centroid when the circumcentre
  // falls outside the domain.
  std::pair<Vec2, std::uint32_t> refinementPoint(std::uint32_t t) const {
    const MetricFrame f = frameAt(centroid(t));
    const Vec2 x = f.invert(circumcenter(f.apply(p(t, 0)), f.apply(p(t, 1)), f.apply(p(t, 2))));
    const std::uint32_t found = tri_.locate(x, t);
    if (found != kNone && inside_[found]) return {x, found};
    return {centroid(t), t};
  }

  // One new point for t: at its refinement point, or in front of its front edge. A triangle
  // whose point cannot go in is kept as it is without waking its neighbours, so that a zone
  // of much smaller sizes which the front first meets at a single vertex is not filled from
  // there (the reference's frontal mesher behaves so).
  bool advanceFront(std::uint32_t t) {
    if (placement_ == Placement::Circumcenter) {
      const auto [x, found] = refinementPoint(t);
      return insert(x, found);
    }
    const std::uint32_t corner = frontCorner(t);
    if (corner == kNone) return false;
    const Vec2 x =
        placement_ == Placement::FrontalQuads ? quadPoint(t, corner) : frontPoint(t, corner);
    if (field_) {
      const std::array<std::uint32_t, 2> ends{tri_.vertex(nextCorner(corner)),
                                              tri_.vertex(prevCorner(corner))};
      if ((*field_)(x) * kLargestStepDown < meanSize(ends)) return false;
    }
    return insert(x, tri_.locate(x, t));
  }

  // Inserts x, found in triangle `found`, unless it falls outside the domain or too close to
  // a vertex or a boundary edge.
  bool insert(Vec2 x, std::uint32_t found) {
    if (found == kNone || !inside_[found]) return false;
    // The triangulation keeps the sizes extended from the boundary, so that a field's small
    // sizes do not spread by interpolation; the field applies where a size is used.
    const double extended = interpolatedSize(found, x);
    const double atX = field_ ? (*field_)(x) : extended;
    const double size = boundedAt(std::min(extended, atX), x);
    if (!(size > 0)) return false;
    const std::uint32_t v = tri_.addPoint(x);
    if (!findCavity(v, found, x) || tooClose(tri_.cavityBoundary(), x, size)) {
      tri_.removeLastPoint();
      return false;
    }
    tri_.setSize(v, extended);
    if (field_) {
      fieldSizes_.resize(tri_.pointCount(), -1);
      fieldSizes_[v] = atX;
    }
    if (placement_ == Placement::FrontalQuads) cross_.push_back(interpolatedCross(found, x));
    tri_.commitCavity(v);
    updateAfterInsertion();
    return true;
  }

  void updateAfterInsertion() {
    for (std::uint32_t t : tri_.created()) {
      if (t >= state_.size()) {
        state_.resize(t + 1, State::Outside);
        stamp_.resize(t + 1, 0);
        inside_.resize(t + 1, 0);
      }
      inside_[t] = 1;
      ++stamp_[t];
      state_[t] = isGood(t) ? State::Accepted : State::Waiting;
    }
    for (std::uint32_t t : tri_.created()) activateIfOnFront(t);
    for (std::uint32_t corner : tri_.cavityRim())
      if (corner != kNone) activateIfOnFront(corner / 3);
  }

  Triangulation2D& tri_;
  std::vector<std::uint8_t>& inside_;
  const SurfaceMetric* metric_;
  const WorkPlaneSize* field_;
  const WorkPlaneSize* bound_;
  Placement placement_;
  double idealRadius_;  // circumradius of the ideal triangle of unit size
  std::vector<Vec2> cross_;
  mutable std::vector<double> fieldSizes_;  // the field's size at each vertex; -1: not yet
  std::vector<State> state_;
  std::vector<std::uint32_t> stamp_;
  std::vector<HeapEntry> heap_;
};

}  // namespace

void refineFrontal(Triangulation2D& tri, std::vector<std::uint8_t>& inside,
                   const SurfaceMetric* metric,
                   const WorkPlaneSize* field,
                   const WorkPlaneSize* bound) {
  FrontalRefiner(tri, inside, metric, field, bound, Placement::Frontal).run();
}

void refineFrontalQuads(Triangulation2D& tri, std::vector<std::uint8_t>& inside,
                        const SurfaceMetric* metric,
                        const WorkPlaneSize* field,
                        const WorkPlaneSize* bound) {
  FrontalRefiner(tri, inside, metric, field, bound, Placement::FrontalQuads).run();
}

void refineDelaunay(Triangulation2D& tri, std::vector<std::uint8_t>& inside,
                    const SurfaceMetric* metric,
                    const WorkPlaneSize* field,
                    const WorkPlaneSize* bound) {
  FrontalRefiner(tri, inside, metric, field, bound, Placement::Circumcenter).run();
}

}  // namespace geomesh
