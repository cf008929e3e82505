// meshCurve: nodes splitting the integral of 1/size along arc length, by Gauss quadrature.
#include "mesh/curves/curve_mesher.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "mesh/core/mesh_error.h"
#include "mesh/curves/transfinite_curve.h"

namespace geomesh {
namespace {

constexpr double kGaussX[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                               0.9061798459386640};
constexpr double kGaussW[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                               0.2369268850561891, 0.2369268850561891};

// The integral of f over [a, b] by 5-point Gauss-Legendre quadrature.
template <class F>
double gauss(double a, double b, F f) {
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  double sum = 0;
  for (int i = 0; i < 5; ++i) sum += kGaussW[i] * f(mid + half * kGaussX[i]);
  return sum * half;
}

double arcLength(const CurveGeometry& g, double a, double b) {
  return gauss(a, b, [&](double t) { return norm(g.firstDerivative(t)); });
}

// Cumulative arc length at evenly spaced parameters, and its inverse.
class ArcLengthTable {
 public:
  ArcLengthTable(const CurveGeometry& g, Interval range) : g_(g), range_(range) {
    s_.push_back(0);
    for (int k = 0; k < kPieces; ++k)
      s_.push_back(s_.back() + arcLength(g, param(k), param(k + 1)));
  }
  double length() const { return s_.back(); }

  // The parameter at arc length sigma: bracket in the table, then Newton steps.
  double parameterAt(double sigma) const {
    const auto it = std::upper_bound(s_.begin(), s_.end(), sigma);
    const int k = std::clamp(static_cast<int>(it - s_.begin()) - 1, 0, kPieces - 1);
    const double t0 = param(k), t1 = param(k + 1);
    const double piece = s_[k + 1] - s_[k];
    double t = piece > 0 ? t0 + (t1 - t0) * (sigma - s_[k]) / piece : t0;
    for (int step = 0; step < 3; ++step) {
      const double speed = norm(g_.firstDerivative(t));
      if (!(speed > 0)) break;
      t = std::clamp(t - (s_[k] + arcLength(g_, t0, t) - sigma) / speed, t0, t1);
    }
    return t;
  }

 private:
  static constexpr int kPieces = 64;
  double param(int k) const {
    return range_.min + (range_.max - range_.min) * static_cast<double>(k) / kPieces;
  }
  const CurveGeometry& g_;
  Interval range_;
  std::vector<double> s_;
};

// The integral of 1/size along the arc length, sampled on a uniform grid (Simpson's rule on
// each cell), and its inverse.
class SizeIntegral {
 public:
  static constexpr int kCells = 2048;
  // Arc lengths where a background field is sampled: every half cell.
  static std::vector<double> fieldSampleArcLengths(double length) {
    std::vector<double> sigma(2 * kCells + 1);
    for (int k = 0; k <= 2 * kCells; ++k) sigma[k] = length * k / (2 * kCells);
    return sigma;
  }
  // `fieldSizes`: empty, or bounds on the size (sampleSizeBounds) at fieldSampleArcLengths;
  // `bendSizes` likewise, bounds that hold even below Mesh.MeshSizeMin.
  SizeIntegral(double length, double startSize, double endSize, const SizeRules& rules,
               std::vector<double> fieldSizes = {}, std::vector<double> bendSizes = {})
      : length_(length), h0_(startSize), h1_(endSize), rules_(rules),
        field_(std::move(fieldSizes)), bend_(std::move(bendSizes)) {
    const double dx = length / kCells;
    cumulative_.push_back(0);
    for (int k = 0; k < kCells; ++k) {
      const double a = k * dx, b = a + dx;
      const double cell = dx / 6 * (1 / size(a) + 4 / size(0.5 * (a + b)) + 1 / size(b));
      cumulative_.push_back(cumulative_.back() + cell);
    }
  }
  double total() const { return cumulative_.back(); }
  double size(double sigma) const {
    const double f = length_ > 0 ? sigma / length_ : 0;
    // Exact at both ends, even for 1e22.
    return std::min(rules_.finish(std::min((1 - f) * h0_ + f * h1_, sampled(field_, f))),
                    sampled(bend_, f));
  }
  // The arc length where the integral reaches `value`.
  double arcLengthAt(double value) const {
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), value);
    const int k = std::clamp(static_cast<int>(it - cumulative_.begin()) - 1, 0, kCells - 1);
    const double cell = cumulative_[k + 1] - cumulative_[k];
    const double f = cell > 0 ? (value - cumulative_[k]) / cell : 0;
    return (k + f) * length_ / kCells;
  }

 private:
  // Samples of a bound at fraction f of the length, interpolated.
  static double sampled(const std::vector<double>& samples, double f) {
    if (samples.empty()) return 1e22;
    const double x = std::clamp(f, 0.0, 1.0) * (samples.size() - 1);
    const std::size_t k = std::min(static_cast<std::size_t>(x), samples.size() - 2);
    const double w = x - static_cast<double>(k);
    return (1 - w) * samples[k] + w * samples[k + 1];
  }

  double length_, h0_, h1_;
  const SizeRules& rules_;
  std::vector<double> field_, bend_;
  std::vector<double> cumulative_;
};

// The curved surfaces the curve bounds whose bends the sizes along it (up to `largest`) could
// outgrow (see bendSize), judged on a few places along the curve.
std::vector<const SurfaceGeometry*> tightlyBentSurfaces(const Model& model,
                                                        const ModelCurve& curve, double largest) {
  std::vector<const SurfaceGeometry*> bent;
  const Interval range = curve.geometry->range();
  constexpr int kPlaces = 32;
  for (int tag : model.upward({1, curve.tag})) {
    const ModelSurface* surface = model.surface(tag);
    if (!surface || !surface->geometry || surface->geometry->isPlane() ||
        hasPole(model, *surface))
      continue;  // see meshSurface: a pole's ring of points does the bend's work there
    for (int k = 0; k <= kPlaces; ++k) {
      const double t = range.min + (range.max - range.min) * k / kPlaces;
      const auto uv = surface->geometry->curveParameters(curve.tag, t);
      if (uv && sizesOutgrowBend(surfaceCurvature(*surface->geometry, *uv), largest)) {
        bent.push_back(surface->geometry.get());
        break;
      }
    }
  }
  return bent;
}

// The parameters of the curve at SizeIntegral's sample arc lengths.
std::vector<double> sampleParameters(const ModelCurve& curve, const ArcLengthTable& arc) {
  const std::vector<double> sigma = SizeIntegral::fieldSampleArcLengths(arc.length());
  const Interval range = curve.geometry->range();
  std::vector<double> ts;
  ts.reserve(sigma.size());
  for (std::size_t k = 0; k < sigma.size(); ++k)
    ts.push_back(arc.length() > 0 ? arc.parameterAt(sigma[k])
                                  : range.min + (range.max - range.min) * k / (sigma.size() - 1));
  return ts;
}

// The bend bound (bendSize) of the surfaces the curve bounds whose bends the sizes along it
// could outgrow, at SizeIntegral's sample arc lengths; empty when no bend is that tight.
std::vector<double> sampleBendBounds(const Model& model, const ModelCurve& curve,
                                     const ArcLengthTable& arc, double largest) {
  const std::vector<const SurfaceGeometry*> bent = tightlyBentSurfaces(model, curve, largest);
  if (bent.empty()) return {};
  const std::vector<double> ts = sampleParameters(curve, arc);
  // Evaluated every `stride` samples, no farther apart than half the largest size, and
  // interpolated between.
  const std::size_t last = ts.size() - 1;
  const double spacing = arc.length() / static_cast<double>(last);
  const std::size_t stride = std::clamp<std::size_t>(
      spacing > 0 ? static_cast<std::size_t>(0.5 * largest / spacing) : last, 1, 16);
  std::vector<double> sizes(ts.size(), 1e22);
  std::size_t previous = 0;
  for (std::size_t k = 0;; k = std::min(k + stride, last)) {
    for (const SurfaceGeometry* g : bent)
      if (const auto uv = g->curveParameters(curve.tag, ts[k]))
        sizes[k] = std::min(sizes[k], bendSize(surfaceCurvature(*g, *uv), largest));
    for (std::size_t j = previous + 1; j < k; ++j) {
      const double w = static_cast<double>(j - previous) / static_cast<double>(k - previous);
      sizes[j] = (1 - w) * sizes[previous] + w * sizes[k];
    }
    previous = k;
    if (k == last) break;
  }
  return sizes;
}

// The size an anisotropic background asks for along the curve's tangent at `t`: 1/sqrt(t'Mt)
// for the unit tangent t; `fallback` where the metric is undefined or degenerate there.
double sizeAlongMetric(const SizeFields& fields, const CurveGeometry& g, int tag, double t,
                       Vec3 point, double fallback) {
  const auto m = fields.metric(point, {1, tag});
  const Vec3 d = g.firstDerivative(t);
  const double length = norm(d);
  if (!m || !(length > 0)) return fallback;
  const Vec3 u = d / length;
  const auto& a = *m;  // xx, xy, xz, yy, yz, zz
  const double q = a[0] * u.x * u.x + a[3] * u.y * u.y + a[5] * u.z * u.z +
                   2 * (a[1] * u.x * u.y + a[2] * u.x * u.z + a[4] * u.y * u.z);
  return q > 0 ? 1 / std::sqrt(q) : fallback;
}

// Bounds on the size besides the end points' sizes, at SizeIntegral's sample arc lengths: the
// background field and the curvature bound (SizeRules::curvatureSize) of the curve and of the
// surfaces it bounds, where they place it. Empty when neither applies.
std::vector<double> sampleSizeBounds(const Model& model, const ModelCurve& curve,
                                     const ArcLengthTable& arc, const SizeRules& rules,
                                     const SizeFields* fields) {
  const bool field = fields && fields->hasBackground();
  if (!field && !(rules.elementsPerTwoPi > 0)) return {};
  const std::vector<double> ts = sampleParameters(curve, arc);
  std::vector<Vec3> points;
  points.reserve(ts.size());
  for (double t : ts) points.push_back(curve.geometry->point(t));
  std::vector<double> sizes(points.size(), 1e22);
  if (field) fields->evaluate(points, {1, curve.tag}, sizes);
  if (field && rules.curvesAlongMetric && fields->hasAnisotropicBackground())
    for (std::size_t k = 0; k < sizes.size(); ++k)
      sizes[k] = sizeAlongMetric(*fields, *curve.geometry, curve.tag, ts[k], points[k], sizes[k]);
  for (std::size_t k = 0; k < sizes.size(); ++k)
    sizes[k] = std::min(sizes[k], rules.curvatureSize(curveCurvature(*curve.geometry, ts[k])));
  if (!(rules.elementsPerTwoPi > 0)) return sizes;
  for (int tag : model.upward({1, curve.tag})) {
    const ModelSurface* surface = model.surface(tag);
    if (!surface || !surface->geometry) continue;
    for (std::size_t k = 0; k < sizes.size(); ++k)
      if (const auto uv = surface->geometry->curveParameters(curve.tag, ts[k]))
        sizes[k] =
            std::min(sizes[k], rules.curvatureSize(surfaceCurvature(*surface->geometry, *uv)));
  }
  return sizes;
}

int segmentCount(double integral, int minimum, bool closed) {
  // Rounded up, except that up to 1% above a whole number is forgiven.
  const int n = std::max(static_cast<int>(std::floor(integral + 0.99)), minimum);
  // Fewer than 3 segments cannot close a loop without overlapping itself.
  return std::max(n, closed ? 3 : 1);
}

void addLines(const std::vector<NodeIndex>& chain, EntityMesh& em) {
  ElementBlock& lines = em.block(ElementType::Line2);
  for (std::size_t k = 0; k + 1 < chain.size(); ++k)
    lines.nodes.insert(lines.nodes.end(), {chain[k], chain[k + 1]});
}

// Nodes at the given fractions of the arc length (Transfinite Curve); each new node's size is
// the mean length of its two segments.
void placeTransfinite(const ModelCurve& curve, const ArcLengthTable& arc,
                      const std::vector<double>& fractions, Mesh& mesh) {
  const CurveGeometry& g = *curve.geometry;
  const Interval range = g.range();
  EntityMesh& em = mesh.entity({1, curve.tag});
  const NodeIndex first = pointNode(mesh, curve.startPoint);
  std::vector<NodeIndex> chain{first};
  const std::size_t segments = fractions.size() - 1;
  for (std::size_t k = 1; k < segments; ++k) {
    const double t = arc.length() > 0
                         ? arc.parameterAt(fractions[k] * arc.length())
                         : range.min + (range.max - range.min) * fractions[k];
    const NodeIndex node = mesh.addNode(g.point(t));
    mesh.setNodeSize(node, 0.5 * arc.length() * (fractions[k + 1] - fractions[k - 1]));
    em.nodes.push_back(node);
    em.parametric.push_back(t);
    chain.push_back(node);
  }
  chain.push_back(pointNode(mesh, curve.endPoint));
  addLines(chain, em);
}

}  // namespace

NodeIndex pointNode(const Mesh& mesh, int pointTag) {
  const EntityMesh* m = mesh.find({0, pointTag});
  if (!m || m->nodes.empty()) throw MeshError({0, pointTag}, "point has no mesh node");
  return m->nodes.front();
}

void meshCurve(const Model& model, const ModelCurve& curve, const SizeRules& rules, Mesh& mesh,
               const SizeFields* fields) {
  const EntityId id{1, curve.tag};
  const ModelPoint* start = model.point(curve.startPoint);
  const ModelPoint* end = model.point(curve.endPoint);
  if (!start || !end) throw MeshError(id, "curve has no end points");
  if (!curve.geometry) throw MeshError(id, "curve has no geometry");
  const CurveGeometry& g = *curve.geometry;
  const Interval range = g.range();
  const bool closed = curve.startPoint == curve.endPoint;

  const ArcLengthTable arc(g, range);
  EntityMesh& em = mesh.entity(id);
  em.nodes.clear();
  em.parametric.clear();
  em.blocks.clear();
  if (g.isDegenerate()) return;  // its mesh is its one vertex
  const auto& transfinite = model.meshConstraints().transfiniteCurves;
  if (const auto it = transfinite.find(curve.tag); it != transfinite.end()) {
    placeTransfinite(curve, arc, transfiniteFractions(it->second), mesh);
    return;
  }
  const auto [startSize, endSize] = rules.curveEndSizes(*start, *end);
  // The largest size the curve could get: its ends' sizes, or the field's bound.
  const bool field = fields && fields->hasBackground();
  const double largest =
      std::min(rules.finish(field ? rules.sizeMax : std::max(startSize, endSize)), arc.length());
  const SizeIntegral integral(arc.length(), startSize, endSize, rules,
                              sampleSizeBounds(model, curve, arc, rules, fields),
                              sampleBendBounds(model, curve, arc, largest));
  if (!std::isfinite(integral.total())) throw MeshError(id, "invalid mesh size along the curve");
  constexpr double kMaxSegments = 1e9;  // node indices are 32-bit
  if (integral.total() > kMaxSegments)
    throw MeshError(id, "the mesh size asks for more than 1e9 segments");
  int segments = segmentCount(integral.total(), rules.minimumSegments(g), closed);
  // A curve shorter than its size keeps its one segment, as in the reference.
  if (segments % 2 != 0 && integral.total() >= 1 && rules.evenCurves.contains(curve.tag))
    ++segments;

  std::vector<NodeIndex> chain{pointNode(mesh, curve.startPoint)};
  for (int k = 1; k < segments; ++k) {
    const double sigma = integral.arcLengthAt(integral.total() * k / segments);
    const double t = arc.length() > 0 ? arc.parameterAt(sigma)
                                      : range.min + (range.max - range.min) * k / segments;
    const NodeIndex node = mesh.addNode(g.point(t));
    mesh.setNodeSize(node, integral.size(sigma));
    em.nodes.push_back(node);
    em.parametric.push_back(t);
    chain.push_back(node);
  }
  chain.push_back(pointNode(mesh, curve.endPoint));
  addLines(chain, em);
}

std::vector<NodeIndex> curveNodeChain(const Model& model, const Mesh& mesh, int signedTag) {
  const int tag = std::abs(signedTag);
  const ModelCurve* curve = model.curve(tag);
  const EntityMesh* em = mesh.find({1, tag});
  if (!curve || !em) throw MeshError({1, tag}, "curve has no mesh");
  std::vector<NodeIndex> chain{pointNode(mesh, curve->startPoint)};
  chain.insert(chain.end(), em->nodes.begin(), em->nodes.end());
  chain.push_back(pointNode(mesh, curve->endPoint));
  if (signedTag < 0) std::reverse(chain.begin(), chain.end());
  return chain;
}

std::vector<double> curveNodeParameters(const Model& model, const Mesh& mesh, int signedTag) {
  const int tag = std::abs(signedTag);
  const ModelCurve* curve = model.curve(tag);
  const EntityMesh* em = mesh.find({1, tag});
  if (!curve || !em || !curve->geometry) throw MeshError({1, tag}, "curve has no mesh");
  if (em->parametric.size() != em->nodes.size()) return {};
  const Interval range = curve->geometry->range();
  std::vector<double> ts{range.min};
  ts.insert(ts.end(), em->parametric.begin(), em->parametric.end());
  ts.push_back(range.max);
  if (signedTag < 0) std::reverse(ts.begin(), ts.end());
  return ts;
}

}  // namespace geomesh
