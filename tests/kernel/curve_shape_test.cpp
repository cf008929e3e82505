// Lengths and enclosed areas of the built-in kernel's Spline, BSpline, Bezier and Nurbs curves,
// built through the factory as a script builds them. Each expected value is computed here from
// the curve's defining formula (written out below, apart from the kernel's own evaluators) or in
// closed form; the comments give the reference's value for the same script (its curves meshed
// with 20001 nodes each, segment lengths summed, the area of the polygon they bound).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "kernel/geo/geo_factory.h"
#include "kernel/model.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

// --- Quadrature -----------------------------------------------------------------------------

struct GaussRule {
  std::vector<double> nodes, weights;  // on [-1, 1]
};

// Gauss-Legendre rule of n points: nodes are the roots of P_n, found by Newton's iteration from
// Chebyshev guesses; weights 2 / ((1 - x^2) P_n'(x)^2).
GaussRule gaussLegendre(int n) {
  const double pi = std::acos(-1.0);
  GaussRule rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double derivative = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = x;  // P_0, P_1, then up to P_n by Bonnet's recursion
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.nodes.push_back(x);
    rule.weights.push_back(2 / ((1 - x * x) * derivative * derivative));
  }
  return rule;
}

// The integral of f over [a, b], cut into `pieces` equal intervals of 16 Gauss points each.
double integrate(const std::function<double(double)>& f, double a, double b, int pieces) {
  static const GaussRule rule = gaussLegendre(16);
  const double h = (b - a) / pieces;
  double sum = 0;
  for (int p = 0; p < pieces; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i)
      sum += rule.weights[i] * f(mid + 0.5 * h * rule.nodes[i]);
  }
  return 0.5 * h * sum;
}

// A curve over [breaks.front(), breaks.back()], smooth between breaks; lengths integrate
// each interval between breaks in `lengthPieces` parts.
struct Arc {
  std::function<Vec3(double)> derivative;
  std::function<Vec3(double)> point;
  std::vector<double> breaks;
  int lengthPieces = 64;
};

double arcLength(const Arc& c) {
  double sum = 0;
  for (std::size_t i = 0; i + 1 < c.breaks.size(); ++i)
    sum += integrate([&](double t) { return norm(c.derivative(t)); }, c.breaks[i], c.breaks[i + 1],
                     c.lengthPieces);
  return sum;
}

// Half the integral of x y' - y x': the area swept from the origin (Green's theorem), which,
// summed over a closed loop, is the area it encloses (positive when counter-clockwise in xy).
double sweptArea(const Arc& c) {
  double sum = 0;
  for (std::size_t i = 0; i + 1 < c.breaks.size(); ++i)
    sum += integrate(
        [&](double t) {
          const Vec3 p = c.point(t), d = c.derivative(t);
          return 0.5 * (p.x * d.y - p.y * d.x);
        },
        c.breaks[i], c.breaks[i + 1], 8);
  return sum;
}

double segmentSweptArea(Vec3 a, Vec3 b) {
  return 0.5 * (a.x * b.y - b.x * a.y);
}

// --- The curves, by their defining formulas --------------------------------------------------

// Catmull-Rom through the points, the parameter running 0..n-1 (one per piece), with the
// points before the first and after the last mirrored: P(-1) = 2 P(0) - P(1).
Arc catmullRom(std::vector<Vec3> p) {
  const std::size_t n = p.size();
  std::vector<Vec3> q{2 * p[0] - p[1]};
  q.insert(q.end(), p.begin(), p.end());
  q.push_back(2 * p[n - 1] - p[n - 2]);
  auto piece = [q](double t, int& i) {
    i = std::min(static_cast<int>(std::floor(t)), static_cast<int>(q.size()) - 4);
    return t - i;
  };
  Arc arc;
  arc.point = [q, piece](double t) {
    int i = 0;
    const double s = piece(t, i);
    const Vec3 a = q[i], b = q[i + 1], c = q[i + 2], d = q[i + 3];
    return 0.5 * (2 * b + s * (c - a) + s * s * (2 * a - 5 * b + 4 * c - d) +
                  s * s * s * (3 * b - a - 3 * c + d));
  };
  arc.derivative = [q, piece](double t) {
    int i = 0;
    const double s = piece(t, i);
    const Vec3 a = q[i], b = q[i + 1], c = q[i + 2], d = q[i + 3];
    return 0.5 *
           ((c - a) + 2 * s * (2 * a - 5 * b + 4 * c - d) + 3 * s * s * (3 * b - a - 3 * c + d));
  };
  for (std::size_t i = 0; i < n; ++i) arc.breaks.push_back(static_cast<double>(i));
  return arc;
}

// Bezier curve in Bernstein form over [0, 1].
Arc bezier(std::vector<Vec3> p) {
  auto bernsteinSum = [](const std::vector<Vec3>& c, double t) {
    const int n = static_cast<int>(c.size()) - 1;
    Vec3 sum;
    double binomial = 1;
    for (int i = 0; i <= n; ++i) {
      sum += binomial * std::pow(t, i) * std::pow(1 - t, n - i) * c[i];
      binomial = binomial * (n - i) / (i + 1);
    }
    return sum;
  };
  std::vector<Vec3> hodograph;
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    hodograph.push_back(static_cast<double>(p.size() - 1) * (p[i + 1] - p[i]));
  Arc arc;
  arc.point = [p, bernsteinSum](double t) { return bernsteinSum(p, t); };
  arc.derivative = [hodograph, bernsteinSum](double t) { return bernsteinSum(hodograph, t); };
  arc.breaks = {0, 1};
  return arc;
}

// B-spline of the given degree and knots by the Cox-de Boor recursion; its derivative is the
// B-spline of degree - 1 on the inner knots with control points
// degree (P[i+1] - P[i]) / (knots[i + degree + 1] - knots[i + 1]).
Vec3 coxDeBoor(const std::vector<Vec3>& p, const std::vector<double>& knots, int degree, double u) {
  // Basis functions of degree 0, then raised one degree at a time; the last span is closed.
  std::vector<double> basis(knots.size() - 1, 0.0);
  const double last = knots[p.size()];
  for (std::size_t i = 0; i + 1 < knots.size(); ++i)
    if (knots[i] < knots[i + 1] &&
        ((u >= knots[i] && u < knots[i + 1]) || (u == last && knots[i + 1] == last)))
      basis[i] = 1;
  for (int d = 1; d <= degree; ++d)
    for (std::size_t i = 0; i + d + 1 < knots.size(); ++i) {
      double value = 0;
      if (knots[i + d] > knots[i]) value += (u - knots[i]) / (knots[i + d] - knots[i]) * basis[i];
      if (knots[i + d + 1] > knots[i + 1])
        value += (knots[i + d + 1] - u) / (knots[i + d + 1] - knots[i + 1]) * basis[i + 1];
      basis[i] = value;
    }
  Vec3 sum;
  for (std::size_t i = 0; i < p.size(); ++i) sum += basis[i] * p[i];
  return sum;
}

Arc bSpline(std::vector<Vec3> p, std::vector<double> knots, int degree) {
  std::vector<Vec3> q;
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    q.push_back(degree / (knots[i + degree + 1] - knots[i + 1]) * (p[i + 1] - p[i]));
  const std::vector<double> inner(knots.begin() + 1, knots.end() - 1);
  Arc arc;
  arc.point = [p, knots, degree](double u) { return coxDeBoor(p, knots, degree, u); };
  arc.derivative = [q, inner, degree](double u) { return coxDeBoor(q, inner, degree - 1, u); };
  for (std::size_t i = degree; i <= p.size(); ++i)
    if (arc.breaks.empty() || knots[i] > arc.breaks.back()) arc.breaks.push_back(knots[i]);
  return arc;
}

// Uniform periodic cubic B-spline of a closed control polygon (distinct points p, the last
// joined back to the first), one piece per point, in matrix form.
Arc periodicCubic(std::vector<Vec3> p) {
  const int n = static_cast<int>(p.size());
  auto corners = [p, n](double t, double& s) {
    const int i = std::min(static_cast<int>(std::floor(t)), n - 1);
    s = t - i;
    return std::vector<Vec3>{p[i], p[(i + 1) % n], p[(i + 2) % n], p[(i + 3) % n]};
  };
  Arc arc;
  arc.point = [corners](double t) {
    double s = 0;
    const std::vector<Vec3> c = corners(t, s);
    return (std::pow(1 - s, 3) * c[0] + (3 * s * s * s - 6 * s * s + 4) * c[1] +
            (-3 * s * s * s + 3 * s * s + 3 * s + 1) * c[2] + s * s * s * c[3]) /
           6;
  };
  arc.derivative = [corners](double t) {
    double s = 0;
    const std::vector<Vec3> c = corners(t, s);
    return (-3 * (1 - s) * (1 - s) * c[0] + (9 * s * s - 12 * s) * c[1] +
            (-9 * s * s + 6 * s + 3) * c[2] + 3 * s * s * c[3]) /
           6;
  };
  for (int i = 0; i <= n; ++i) arc.breaks.push_back(i);
  return arc;
}

// --- The kernel's curves ---------------------------------------------------------------------

// A curve of the model as an Arc over its parameter range, split in 400 (the kernel's pieces
// fall on multiples of 1/400 in every case here).
Arc modelArc(const Model& model, int tag) {
  const CurveGeometry& g = *model.curve(tag)->geometry;
  Arc arc;
  arc.point = [&g](double t) { return g.point(t); };
  arc.derivative = [&g](double t) { return g.firstDerivative(t); };
  const Interval r = g.range();
  for (int i = 0; i <= 400; ++i) arc.breaks.push_back(r.min + (r.max - r.min) * i / 400);
  arc.lengthPieces = 2;
  return arc;
}

double modelLength(const Model& model, int tag) {
  return arcLength(modelArc(model, tag));
}

// The area the outer loop of a plane surface in z = 0 encloses, from its curves.
double modelArea(const Model& model, int surface) {
  double area = 0;
  for (int signedTag : model.surface(surface)->loops.front()) {
    const double swept = sweptArea(modelArc(model, std::abs(signedTag)));
    area += signedTag > 0 ? swept : -swept;
  }
  return std::abs(area);
}

void addPoints(GeoFactory& geo, const std::vector<Vec3>& points) {
  for (std::size_t i = 0; i < points.size(); ++i)
    geo.addPoint(static_cast<int>(i) + 1, points[i], 0);
}

std::vector<int> firstTags(int n) {
  std::vector<int> tags;
  for (int i = 1; i <= n; ++i) tags.push_back(i);
  return tags;
}

// --- Spline ---------------------------------------------------------------------------------

TEST(CurveShape, SplineInterpolatesWithMirroredEnds) {
  const std::vector<Vec3> p = {
      {0, 0, 0}, {1, 0.6, 0.3}, {2, -0.2, 0.5}, {3.2, 0.7, 0.2}, {4, 0, 0}};
  GeoFactory geo;
  addPoints(geo, p);
  geo.addSpline(1, firstTags(5));
  Model model;
  geo.synchronize(model);
  const CurveGeometry& g = *model.curve(1)->geometry;
  for (int i = 0; i < 5; ++i) expectNear(g.point(i / 4.0), p[i], 1e-12);
  // Reference: 5.2379546 (5.2379546346).
  const double expected = arcLength(catmullRom(p));
  EXPECT_NEAR(expected, 5.2379546, 1e-6);
  EXPECT_NEAR(modelLength(model, 1), expected, 1e-9);
  // End conditions: mirrored points make each end tangent run along the first (last) chord;
  // the reference's first segment points along (0.830401, 0.498367, 0.249129) = P1 - P0, and its
  // last along (0.739496, -0.647277, -0.184874) = P4 - P3, normalized.
  expectNear(normalized(g.firstDerivative(0)), normalized(p[1] - p[0]), 1e-12);
  expectNear(normalized(g.firstDerivative(1)), normalized(p[4] - p[3]), 1e-12);
}

TEST(CurveShape, LoopOfThreeSplinesEnclosesItsArea) {
  const std::vector<Vec3> p = {{1, 0, 0},  {0.5, 0.9, 0},   {-0.5, 0.85, 0},
                               {-1, 0, 0}, {-0.5, -0.9, 0}, {0.6, -0.8, 0}};
  GeoFactory geo;
  addPoints(geo, p);
  geo.addSpline(1, {1, 2, 3});
  geo.addSpline(2, {3, 4, 5});
  geo.addSpline(3, {5, 6, 1});
  geo.addCurveLoop(1, {1, 2, 3});
  geo.addPlaneSurface(1, {1});
  Model model;
  geo.synchronize(model);
  // Reference lengths 2.0613875, 2.0432735, 2.0261802; area 2.8525000 (2.8524999972).
  const Arc a1 = catmullRom({p[0], p[1], p[2]}), a2 = catmullRom({p[2], p[3], p[4]}),
            a3 = catmullRom({p[4], p[5], p[0]});
  const double lengths[] = {arcLength(a1), arcLength(a2), arcLength(a3)};
  const double reference[] = {2.0613875, 2.0432735, 2.0261802};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(lengths[i], reference[i], 1e-6);
    EXPECT_NEAR(modelLength(model, i + 1), lengths[i], 1e-9);
  }
  const double area = sweptArea(a1) + sweptArea(a2) + sweptArea(a3);
  EXPECT_NEAR(area, 2.8525, 1e-6);
  EXPECT_NEAR(modelArea(model, 1), area, 1e-9);
}

// --- BSpline --------------------------------------------------------------------------------

TEST(CurveShape, OpenBSplineIsAClampedUniformCubic) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 2, 0}, {3, 2.5, 0}, {4, 0, 0}, {6, 1, 0}, {7, -1, 0}};
  GeoFactory geo;
  addPoints(geo, p);
  geo.addBSpline(1, firstTags(6));
  geo.addLine(2, 6, 1);
  geo.addCurveLoop(1, {1, 2});
  geo.addPlaneSurface(1, {1});
  Model model;
  geo.synchronize(model);
  expectNear(model.curve(1)->geometry->point(0), p.front(), 1e-12);
  expectNear(model.curve(1)->geometry->point(1), p.back(), 1e-12);
  // Reference: length 9.1585820 (9.1585819881), area 10.3229166 (10.3229166280).
  const Arc arc = bSpline(p, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3}, 3);
  const double length = arcLength(arc);
  const double area = std::abs(sweptArea(arc) + segmentSweptArea(p.back(), p.front()));
  EXPECT_NEAR(length, 9.1585820, 1e-6);
  EXPECT_NEAR(area, 10.3229166, 1e-6);
  EXPECT_NEAR(modelLength(model, 1), length, 1e-9);
  EXPECT_NEAR(modelArea(model, 1), area, 1e-9);
}

// A quadratic clamped BSpline of three points is the Bezier curve of the same points: here the
// parabola y = x^2 for x in [-1, 1]. Reference, both: length 2.9578857 (2.9578857127), area
// 1.3333333 (1.3333333293).
TEST(CurveShape, BSplineOfThreePointsAndQuadraticBezierAreAParabola) {
  for (const bool bezier : {false, true}) {
    SCOPED_TRACE(bezier ? "Bezier" : "BSpline");
    GeoFactory geo;
    addPoints(geo, {{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}});
    if (bezier)
      geo.addBezier(1, {1, 2, 3});
    else
      geo.addBSpline(1, {1, 2, 3});
    geo.addLine(2, 3, 1);
    geo.addCurveLoop(1, {1, 2});
    geo.addPlaneSurface(1, {1});
    Model model;
    geo.synchronize(model);
    EXPECT_NEAR(modelLength(model, 1), std::sqrt(5.0) + std::asinh(2.0) / 2, 1e-9);
    EXPECT_NEAR(modelArea(model, 1), 4.0 / 3, 1e-9);
  }
}

TEST(CurveShape, ClosedBSplineIsPeriodic) {
  const std::vector<Vec3> p = {{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {1, 3, 0}, {-1, 1, 0}};
  GeoFactory geo;
  addPoints(geo, p);
  geo.addBSpline(1, {1, 2, 3, 4, 5, 1});
  geo.addCurveLoop(1, {1});
  geo.addPlaneSurface(1, {1});
  Model model;
  geo.synchronize(model);
  const CurveGeometry& g = *model.curve(1)->geometry;
  expectNear(g.point(0), g.point(1), 1e-12);
  expectNear(g.firstDerivative(0), g.firstDerivative(1), 1e-12);
  // The curve starts at (P4 + 4 P0 + P1) / 6, not at P0: the reference's first and last
  // segments both point along (0.970, -0.243), the tangent (P1 - P4) / 2 there.
  expectNear(g.point(0), (p[4] + 4 * p[0] + p[1]) / 6, 1e-12);
  expectNear(normalized(g.firstDerivative(0)), normalized(p[1] - p[4]), 1e-12);
  // Reference: length 9.3862090 (9.3862089617), area 6.6250000 (6.6249998847).
  const Arc arc = periodicCubic(p);
  const double length = arcLength(arc), area = std::abs(sweptArea(arc));
  EXPECT_NEAR(length, 9.3862090, 1e-6);
  EXPECT_NEAR(area, 6.625, 1e-6);
  EXPECT_NEAR(modelLength(model, 1), length, 1e-9);
  EXPECT_NEAR(modelArea(model, 1), area, 1e-9);
}

// --- Bezier ---------------------------------------------------------------------------------

TEST(CurveShape, CubicBezier) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}};
  GeoFactory geo;
  addPoints(geo, p);
  geo.addBezier(1, firstTags(4));
  geo.addLine(2, 4, 1);
  geo.addCurveLoop(1, {1, 2});
  geo.addPlaneSurface(1, {1});
  Model model;
  geo.synchronize(model);
  // Reference: length 5.2683655 (5.2683655401), area 4.2000000 (4.1999999872). In closed form:
  // x = 3t + 3t^2 - 2t^3 and y = 6t(1 - t), so with u = t(1 - t) the area under the curve is
  // the integral of 6u (3 + 6u) dt over [0, 1], 18/6 + 36/30 = 4.2.
  const Arc arc = bezier(p);
  const double length = arcLength(arc);
  EXPECT_NEAR(length, 5.2683655, 1e-6);
  EXPECT_NEAR(std::abs(sweptArea(arc) + segmentSweptArea(p.back(), p.front())), 4.2, 1e-12);
  EXPECT_NEAR(modelLength(model, 1), length, 1e-9);
  EXPECT_NEAR(modelArea(model, 1), 4.2, 1e-9);
}

// --- Nurbs ----------------------------------------------------------------------------------

TEST(CurveShape, NurbsWithClampedNonUniformKnots) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 1.5, 0},  {2.5, 2, 0},
                               {4, 1, 0}, {5, -0.5, 0}, {6, 0.5, 0}};
  const std::vector<double> knots = {0, 0, 0, 0, 0.3, 0.5, 1, 1, 1, 1};
  GeoFactory geo;
  addPoints(geo, p);
  geo.addNurbs(1, firstTags(6), knots, 3);
  geo.addLine(2, 6, 1);
  geo.addCurveLoop(1, {1, 2});
  geo.addPlaneSurface(1, {1});
  Model model;
  geo.synchronize(model);
  // Reference: length 7.3558948 (7.3558948085), area 4.1819235 (4.1819234656).
  const Arc arc = bSpline(p, knots, 3);
  const double length = arcLength(arc);
  const double area = std::abs(sweptArea(arc) + segmentSweptArea(p.back(), p.front()));
  EXPECT_NEAR(length, 7.3558948, 1e-6);
  EXPECT_NEAR(area, 4.1819235, 1e-6);
  EXPECT_NEAR(modelLength(model, 1), length, 1e-9);
  EXPECT_NEAR(modelArea(model, 1), area, 1e-9);
}

}  // namespace
}  // namespace geomesh
