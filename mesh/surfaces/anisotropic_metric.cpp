// Eigen decomposition, intersection, frames and restriction of 2x2 metrics.
#include "mesh/surfaces/anisotropic_metric.h"

#include <algorithm>
#include <cmath>

namespace geomesh {

MetricEigen eigen(Metric2 m) {
  const double half = 0.5 * (m.a + m.c), gap = 0.5 * (m.a - m.c);
  const double r = std::hypot(gap, m.b);
  MetricEigen e;
  e.large = half + r;
  e.small = half - r;
  if (!(r > 0)) return e;
  // Of the two candidate eigenvectors, the one with the larger norm is the better conditioned.
  const Vec2 p{e.large - m.c, m.b}, q{m.b, e.large - m.a};
  const double np = std::hypot(p.u, p.v), nq = std::hypot(q.u, q.v);
  e.direction = np >= nq ? Vec2{p.u / np, p.v / np} : Vec2{q.u / nq, q.v / nq};
  return e;
}

Metric2 fromEigen(const MetricEigen& e) {
  const double x = e.direction.u, y = e.direction.v;
  return {e.large * x * x + e.small * y * y, (e.large - e.small) * x * y,
          e.large * y * y + e.small * x * x};
}

Metric2 isotropicMetric(double h) {
  const double m = 1 / (h * h);
  return {m, 0, m};
}

Metric2 scaled(Metric2 m, double factor) {
  return {m.a * factor, m.b * factor, m.c * factor};
}

double lengthSquared(Metric2 m, Vec2 d) {
  return std::max(m.a * d.u * d.u + 2 * m.b * d.u * d.v + m.c * d.v * d.v, 0.0);
}

bool isPositiveDefinite(Metric2 m) {
  return std::isfinite(m.a) && std::isfinite(m.b) && std::isfinite(m.c) && m.a > 0 &&
         m.a * m.c - m.b * m.b > 0;
}

Metric2 mean(Metric2 a, Metric2 b, Metric2 c) {
  return {(a.a + b.a + c.a) / 3, (a.b + b.b + c.b) / 3, (a.c + b.c + c.c) / 3};
}

// F^-T M F^-1 entry by entry: the form of M on the columns of F^-1 (and of F for the inverse).
Metric2 inFrame(Metric2 m, const MetricFrame& f) {
  const Vec2 c1 = f.invert({1, 0}), c2 = f.invert({0, 1});
  const auto form = [&](Vec2 x, Vec2 y) {
    return m.a * x.u * y.u + m.b * (x.u * y.v + x.v * y.u) + m.c * x.v * y.v;
  };
  return {form(c1, c1), form(c1, c2), form(c2, c2)};
}

Metric2 outOfFrame(Metric2 m, const MetricFrame& f) {
  const Vec2 c1 = f.apply({1, 0}), c2 = f.apply({0, 1});
  const auto form = [&](Vec2 x, Vec2 y) {
    return m.a * x.u * y.u + m.b * (x.u * y.v + x.v * y.u) + m.c * x.v * y.v;
  };
  return {form(c1, c1), form(c1, c2), form(c2, c2)};
}

namespace {

// b seen from a's Cholesky frame, where a is the identity: its eigenvalues above 1 are the
// directions where b asks for smaller sizes than a.
MetricEigen relativeEigen(Metric2 a, Metric2 b, MetricFrame& frame) {
  frame = MetricFrame(a);
  return eigen(inFrame(b, frame));
}

}  // namespace

Metric2 intersect(Metric2 a, Metric2 b) {
  MetricFrame frame;
  MetricEigen e = relativeEigen(a, b, frame);
  e.large = std::max(e.large, 1.0);
  e.small = std::max(e.small, 1.0);
  return outOfFrame(fromEigen(e), frame);
}

bool intersectInto(Metric2& m, Metric2 other, double tolerance) {
  MetricFrame frame;
  MetricEigen e = relativeEigen(m, other, frame);
  if (!(e.large > 1 + tolerance)) return false;
  e.large = std::max(e.large, 1.0);
  e.small = std::max(e.small, 1.0);
  m = outOfFrame(fromEigen(e), frame);
  return true;
}

Metric2 restrictMetric(const std::array<double, 6>& m, Vec3 t1, Vec3 t2) {
  const auto apply = [&](Vec3 t) {
    return Vec3{m[0] * t.x + m[1] * t.y + m[2] * t.z, m[1] * t.x + m[3] * t.y + m[4] * t.z,
                m[2] * t.x + m[4] * t.y + m[5] * t.z};
  };
  const Vec3 m1 = apply(t1), m2 = apply(t2);
  return {dot(t1, m1), 0.5 * (dot(t2, m1) + dot(t1, m2)), dot(t2, m2)};
}

Metric2 grownAlong(Metric2 m, Vec2 d, double rate) {
  const double eta = 1 + std::sqrt(lengthSquared(m, d)) * rate;
  return scaled(m, 1 / (eta * eta));
}

}  // namespace geomesh
