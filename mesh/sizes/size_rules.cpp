// SizeRules: point sizes, clamping, curvature bounds and minimum segments by curve shape.
#include "mesh/sizes/size_rules.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>


namespace geomesh {
namespace {

constexpr double kUnbounded = 1e22;
constexpr double kPi = 3.14159265358979323846;

// Parameters where a curve is probed to recognise its shape.
std::vector<double> probeParameters(const CurveGeometry& g) {
  const Interval r = g.range();
  std::vector<double> t;
  for (int k = 0; k <= 8; ++k) t.push_back(r.min + (r.max - r.min) * (0.05 + 0.9 * k / 8));
  return t;
}

// A circle or ellipse parametrized by its angle, c + a cos(t) u + b sin(t) v, is the one curve
// whose point plus second derivative is its center everywhere.
bool isAngleParametrizedConic(const CurveGeometry& g) {
  const std::vector<double> ts = probeParameters(g);
  const Vec3 center = g.point(ts[0]) + g.secondDerivative(ts[0]);
  const double scale = distance(g.point(ts[0]), center);
  if (!(scale > 0)) return false;
  for (double t : ts)
    if (distance(g.point(t) + g.secondDerivative(t), center) > 1e-9 * scale) return false;
  return true;
}

// No curvature anywhere, relative to the curve's extent.
bool isStraight(const CurveGeometry& g) {
  const std::vector<double> ts = probeParameters(g);
  double extent = 0;
  for (double t : ts) extent = std::max(extent, distance(g.point(t), g.point(ts[0])));
  for (double t : ts)
    if (curveCurvature(g, t) * extent > 1e-12) return false;
  return true;
}

// The three kinds of curves the minimum segment counts tell apart, as Gmsh names them.
enum class CurveShape { Line, Arc, Other };

// Curves say what they are; a spline stays a spline even when straight. Curves of no known
// kind are recognised by their shape.
CurveShape shapeOf(const CurveGeometry& g) {
  switch (g.kind()) {
    case CurveKind::Line: return CurveShape::Line;
    case CurveKind::CircleArc:
    case CurveKind::EllipseArc: return CurveShape::Arc;
    case CurveKind::Spline:
    case CurveKind::BSpline:
    case CurveKind::Bezier: return CurveShape::Other;
    case CurveKind::Other: break;
  }
  if (isAngleParametrizedConic(g)) return CurveShape::Arc;
  return isStraight(g) ? CurveShape::Line : CurveShape::Other;
}

}  // namespace

double curveCurvature(const CurveGeometry& g, double t) {
  const Vec3 d1 = g.firstDerivative(t);
  const double speed = norm(d1);
  if (!(speed > 0)) return 0;
  return norm(cross(d1, g.secondDerivative(t))) / (speed * speed * speed);
}

namespace {

// The unit normal at uv; zero where du x dv vanishes.
Vec3 unitNormal(const SurfaceGeometry& g, Vec2 uv) {
  const SurfaceDerivatives d = g.firstDerivatives(uv);
  const Vec3 n = cross(d.du, d.dv);
  const double length = norm(n);
  return length > 0 ? (1 / length) * n : Vec3{};
}

}  // namespace

namespace {
// Elements per full turn of a bend, about as many as circles get (Mesh.MinimumCircleNodes).
constexpr double kElementsPerBend = 6;
}  // namespace

double bendSize(double curvature, double largest) {
  constexpr double kFloor = 0.1;
  if (!(curvature > 0)) return kUnbounded;
  return std::max(2 * std::numbers::pi / (kElementsPerBend * curvature), kFloor * largest);
}

// An element spanning up to a quarter turn of a bend still faces out at its corners (a fillet
// of radius 0.08 under size 0.12 is left as it is); beyond, the bend bound applies.
bool sizesOutgrowBend(double curvature, double largest) {
  return curvature > 0 && largest * curvature > std::numbers::pi / 2;
}

bool hasPole(const Model& model, const ModelSurface& surface) {
  for (const std::vector<int>& loop : surface.loops)
    for (int c : loop)
      if (const ModelCurve* curve = model.curve(std::abs(c)))
        if (curve->geometry && curve->geometry->isDegenerate()) return true;
  return false;
}

// Principal curvatures are the roots k of det(II - k I) = 0, with the first fundamental form
// I = (E, F, G) and the second II = (L, M, N) = -(n_u.x_u, (n_u.x_v + n_v.x_u) / 2, n_v.x_v).
double surfaceCurvature(const SurfaceGeometry& g, Vec2 uv) {
  if (const std::optional<double> known = g.curvature(uv)) return *known;
  const ParamBox box = g.bounds();
  const double hu = 1e-5 * std::max(1.0, std::abs(box.u.max - box.u.min));
  const double hv = 1e-5 * std::max(1.0, std::abs(box.v.max - box.v.min));
  if (!std::isfinite(hu) || !std::isfinite(hv)) return 0;
  SurfaceDerivatives d = g.firstDerivatives(uv);
  // At a pole the first fundamental form degenerates (one tangent vanishes) and the formula
  // divides by nearly nothing: the curvature is read a little way off it, towards the box's
  // centre, where the surface is regular.
  const double su = dot(d.du, d.du), sv = dot(d.dv, d.dv);
  if (su < 1e-12 * sv || sv < 1e-12 * su) {
    constexpr double kStep = 1e-3;
    uv = {uv.u + kStep * (0.5 * (box.u.min + box.u.max) - uv.u),
          uv.v + kStep * (0.5 * (box.v.min + box.v.max) - uv.v)};
    d = g.firstDerivatives(uv);
  }
  // The normal's change over a step that stays within the parameter box: past its edge (a
  // pole, where the surface closes on a point) the surface folds back and the normal turns
  // over, which would read as a huge curvature.
  auto change = [&](double at, double step, Interval range, auto normalAt) {
    const double a = std::max(at - step, std::min(range.min, at));
    const double b = std::min(at + step, std::max(range.max, at));
    return b > a ? (1 / (b - a)) * (normalAt(b) - normalAt(a)) : Vec3{};
  };
  const Vec3 nu = change(uv.u, hu, box.u, [&](double u) { return unitNormal(g, {u, uv.v}); });
  const Vec3 nv = change(uv.v, hv, box.v, [&](double v) { return unitNormal(g, {uv.u, v}); });
  const double e = dot(d.du, d.du), f = dot(d.du, d.dv), gg = dot(d.dv, d.dv);
  const double l = -dot(nu, d.du), m = -0.5 * (dot(nu, d.dv) + dot(nv, d.du)), n = -dot(nv, d.dv);
  const double area = e * gg - f * f;
  if (!(area > 1e-20 * (e * gg)) || !(e > 0) || !(gg > 0)) return 0;
  const double gauss = (l * n - m * m) / area;
  const double mean = (e * n + gg * l - 2 * f * m) / (2 * area);
  const double k = std::abs(mean) + std::sqrt(std::max(0.0, mean * mean - gauss));
  return std::isfinite(k) ? k : 0;
}

SizeRules SizeRules::from(const Model& model, const MeshOptions& options) {
  SizeRules rules;
  rules.sizeMin = options.sizeMin;
  rules.sizeMax = options.sizeMax;
  rules.factor = options.sizeFactor > 0 ? options.sizeFactor : 1;
  rules.fromPoints = options.sizeFromPoints;
  rules.extendFromBoundary = options.sizeExtendFromBoundary;
  rules.defaultSize = defaultSizeOf(model.sizeBox());
  rules.elementsPerTwoPi = std::max(options.sizeFromCurvature, 0.0);
  rules.minCircleNodes = options.minCircleNodes;
  rules.minCurveNodes = options.minCurveNodes;
  rules.curvesAlongMetric = options.algorithm2D == 7;
  const MeshConstraints& constraints = model.meshConstraints();
  if (options.recombinationAlgorithm == 1)
    for (const auto& [tag, surface] : model.surfaces())
      if ((options.recombineAll || constraints.recombinedSurfaces.contains(tag)) &&
          !constraints.transfiniteSurfaces.contains(tag))
        for (int curve : model.boundary({2, tag})) rules.evenCurves.insert(std::abs(curve));
  if (rules.elementsPerTwoPi > 0)
    for (const auto& entry : model.curves()) {
      const ModelCurve& curve = entry.second;
      if (!curve.geometry) continue;
      const Interval r = curve.geometry->range();
      const auto bound = [&](int point, double t) {
        const double size = rules.curvatureSize(curveCurvature(*curve.geometry, t));
        auto [it, inserted] = rules.pointCurvatureSizes.try_emplace(point, size);
        if (!inserted) it->second = std::min(it->second, size);
      };
      bound(curve.startPoint, r.min);
      bound(curve.endPoint, r.max);
    }
  return rules;
}

namespace {

// A point's own size, 0 when it has none: a size of 1e22 or more, the reference's "unset"
// value that scripts written by its interface carry, is none too.
double ownSize(const ModelPoint& p) {
  constexpr double kUnset = 1e22;
  return p.meshSize > 0 && p.meshSize < kUnset ? p.meshSize : 0;
}

}  // namespace

double defaultSizeOf(const BoundingBox& box) {
  if (box.empty()) return 1;
  const Vec3 extent = box.max - box.min;
  const double diagonal = norm(extent);
  if (!(diagonal > 0)) return 1;
  // As the reference measures a model: an x or y extent of zero (a model drawn in the x-z
  // plane, or along one axis) counts as twice the diagonal.
  const double x = extent.x > 0 ? extent.x : 2 * diagonal;
  const double y = extent.y > 0 ? extent.y : 2 * diagonal;
  return norm(Vec3{x, y, extent.z}) / 10;
}

std::pair<double, double> SizeRules::curveEndSizes(const ModelPoint& start,
                                                   const ModelPoint& end) const {
  if (!fromPoints) return {kUnbounded, kUnbounded};
  const double a = ownSize(start);
  const double b = ownSize(end);
  if (a == 0 && b == 0) return {defaultSize, defaultSize};
  return {a > 0 ? a : kUnbounded, b > 0 ? b : kUnbounded};
}

double SizeRules::pointSize(const ModelPoint& p) const {
  const double own = !fromPoints ? kUnbounded : ownSize(p) > 0 ? ownSize(p) : defaultSize;
  return std::min(own, curvatureBound(p.tag));
}

double SizeRules::curvatureBound(int pointTag) const {
  const auto it = pointCurvatureSizes.find(pointTag);
  return it == pointCurvatureSizes.end() ? kUnbounded : it->second;
}

double SizeRules::curvatureSize(double curvature) const {
  if (!(elementsPerTwoPi > 0) || !(curvature > 0)) return kUnbounded;
  return 2 * kPi / (elementsPerTwoPi * curvature);
}

int SizeRules::minimumSegments(const CurveGeometry& g) const {
  switch (shapeOf(g)) {
    case CurveShape::Line: return 1;
    case CurveShape::Arc: {
      // Up to 1% of a segment above a whole number is forgiven, as for sizes.
      const double n = std::floor(minCircleNodes * g.arcAngle() / (2 * kPi) + 0.99);
      return std::max(static_cast<int>(n), 1);
    }
    case CurveShape::Other: break;
  }
  return std::max(minCurveNodes - 1, 1);
}

double SizeRules::finish(double rawSize) const {
  // The lower bound wins when the bounds contradict each other.
  return std::max(std::min(rawSize, sizeMax), sizeMin) * factor;
}

}  // namespace geomesh
