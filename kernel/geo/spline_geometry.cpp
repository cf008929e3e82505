// Cox-de Boor evaluation of B-spline and Bezier curves, and Catmull-Rom interpolating splines.
#include "kernel/geo/spline_geometry.h"

#include <algorithm>
#include <cmath>

#include "kernel/geometry_error.h"

namespace geomesh {

namespace {

// Values of the B-spline basis functions of degree `degree` at u: index i is N_{i,degree}.
// Built up from degree 0 by the Cox-de Boor recursion (0/0 counts as 0).
std::vector<double> basisFunctions(const std::vector<double>& knots, int degree, double u,
                                   std::size_t span) {
  const std::size_t count = knots.size() - 1;
  std::vector<double> n(count, 0.0);
  n[span] = 1;
  for (int p = 1; p <= degree; ++p)
    for (std::size_t i = 0; i + p < count; ++i) {
      double value = 0;
      const double left = knots[i + p] - knots[i];
      const double right = knots[i + p + 1] - knots[i + 1];
      if (left > 0) value += (u - knots[i]) / left * n[i];
      if (right > 0) value += (knots[i + p + 1] - u) / right * n[i + 1];
      n[i] = value;
    }
  return n;
}

// The knot span holding u: knots[span] <= u < knots[span + 1], the last non-empty span at the
// end of the domain.
std::size_t knotSpan(const std::vector<double>& knots, int degree, std::size_t pointCount,
                     double u) {
  std::size_t span = static_cast<std::size_t>(degree);
  while (span + 1 < pointCount && knots[span + 1] <= u) ++span;
  return span;
}

}  // namespace

BSplineGeometry::BSplineGeometry(std::vector<Vec3> points, int degree, std::vector<double> knots,
                                 CurveKind kind)
    : points_(std::move(points)), degree_(degree), knots_(std::move(knots)), kind_(kind) {
  if (degree_ < 1 || points_.size() < static_cast<std::size_t>(degree_) + 1 ||
      knots_.size() != points_.size() + static_cast<std::size_t>(degree_) + 1)
    throw GeometryError("B-spline: " + std::to_string(points_.size()) +
                        " control points do not fit degree " + std::to_string(degree_));
  start_ = knots_[static_cast<std::size_t>(degree_)];
  scale_ = knots_[points_.size()] - start_;
}

BSplineGeometry BSplineGeometry::uniform(std::vector<Vec3> points, bool closed) {
  if (closed && points.size() >= 4) {
    // Periodic: the distinct points, wrapped so that every piece has four neighbours; the
    // curve starts next to the first point, at (last + 4 first + second) / 6.
    points.pop_back();
    const std::size_t n = points.size();
    std::vector<Vec3> wrapped{points[n - 1]};
    wrapped.insert(wrapped.end(), points.begin(), points.end());
    wrapped.push_back(points[0]);
    wrapped.push_back(points[1]);
    std::vector<double> knots;
    for (std::size_t i = 0; i < wrapped.size() + 4; ++i)
      knots.push_back(static_cast<double>(i) - 3.0);
    return BSplineGeometry(std::move(wrapped), 3, std::move(knots));
  }
  const int degree = std::min(3, static_cast<int>(points.size()) - 1);
  const int pieces = static_cast<int>(points.size()) - degree;
  std::vector<double> knots(static_cast<std::size_t>(degree), 0.0);
  for (int i = 0; i <= pieces; ++i) knots.push_back(static_cast<double>(i) / pieces);
  knots.insert(knots.end(), static_cast<std::size_t>(degree), 1.0);
  return BSplineGeometry(std::move(points), degree, std::move(knots));
}

BSplineGeometry BSplineGeometry::bezier(std::vector<Vec3> points) {
  const int degree = static_cast<int>(points.size()) - 1;
  std::vector<double> knots(points.size(), 0.0);
  knots.insert(knots.end(), points.size(), 1.0);
  return BSplineGeometry(std::move(points), degree, std::move(knots), CurveKind::Bezier);
}

// Derivatives come from the basis of lower degree: d/du N_{i,p} = p N_{i,p-1} / (k[i+p] - k[i])
// - p N_{i+1,p-1} / (k[i+p+1] - k[i+1]), applied `order` times to the control points instead
// (the derivative of a B-spline is a B-spline of the differences of its control points).
Vec3 BSplineGeometry::evaluate(double t, int order) const {
  const double u = start_ + std::clamp(t, 0.0, 1.0) * scale_;
  std::vector<Vec3> control = points_;
  int degree = degree_;
  std::size_t first = 0;  // knot index matching control[0]
  for (int k = 0; k < order; ++k) {
    if (degree == 0) return {};
    std::vector<Vec3> next;
    for (std::size_t i = 0; i + 1 < control.size(); ++i) {
      const double width = knots_[first + i + 1 + degree] - knots_[first + i + 1];
      next.push_back(width > 0 ? degree / width * (control[i + 1] - control[i]) : Vec3{});
    }
    control = std::move(next);
    --degree;
    ++first;
  }
  const std::vector<double> knots(knots_.begin() + static_cast<std::ptrdiff_t>(first),
                                  knots_.end() - static_cast<std::ptrdiff_t>(first));
  const std::size_t span = knotSpan(knots, degree, control.size(), u);
  const std::vector<double> n = basisFunctions(knots, degree, u, span);
  Vec3 sum;
  for (std::size_t i = 0; i < control.size(); ++i) sum += n[i] * control[i];
  for (int k = 0; k < order; ++k) sum = sum * scale_;
  return sum;
}

CatmullRomGeometry::CatmullRomGeometry(std::vector<Vec3> points)
    : points_(std::move(points)), closed_(points_.size() > 2 && points_.front() == points_.back()) {
  if (points_.size() < 2) throw GeometryError("Spline: needs at least 2 points");
}

Vec3 CatmullRomGeometry::controlPoint(int i) const {
  const int n = static_cast<int>(points_.size());
  if (i >= 0 && i < n) return points_[static_cast<std::size_t>(i)];
  if (closed_) return i < 0 ? points_[static_cast<std::size_t>(n - 2)] : points_[1];
  if (n == 2 || i < 0) return i < 0 ? 2 * points_[0] - points_[1] : 2 * points_[1] - points_[0];
  return 2 * points_[static_cast<std::size_t>(n - 1)] - points_[static_cast<std::size_t>(n - 2)];
}

Vec3 CatmullRomGeometry::evaluate(double t, int order) const {
  const int pieces = static_cast<int>(points_.size()) - 1;
  const double s = std::clamp(t, 0.0, 1.0) * pieces;
  const int i = std::min(static_cast<int>(std::floor(s)), pieces - 1);
  const double x = s - i;
  const Vec3 p0 = controlPoint(i - 1), p1 = controlPoint(i), p2 = controlPoint(i + 1),
             p3 = controlPoint(i + 2);
  // Half of: 2 p1 + (p2 - p0) x + (2 p0 - 5 p1 + 4 p2 - p3) x^2 + (3 p1 - p0 - 3 p2 + p3) x^3.
  const Vec3 c1 = p2 - p0, c2 = 2 * p0 - 5 * p1 + 4 * p2 - p3, c3 = 3 * p1 - p0 - 3 * p2 + p3;
  const double k = pieces;
  switch (order) {
    case 0: return 0.5 * (2 * p1 + x * c1 + x * x * c2 + x * x * x * c3);
    case 1: return 0.5 * k * (c1 + 2 * x * c2 + 3 * x * x * c3);
    default: return 0.5 * k * k * (2 * c2 + 6 * x * c3);
  }
}

}  // namespace geomesh
