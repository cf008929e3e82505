// WorkFrame, SurfaceMetric and MetricFrame: the first fundamental form in work-plane terms.
#include "mesh/surfaces/surface_metric.h"

#include <cmath>

namespace geomesh {

WorkFrame::WorkFrame(const SurfaceGeometry& g, Vec2 origin) : origin_(origin) {
  const SurfaceDerivatives d = g.firstDerivatives(origin);
  const double a11 = norm(d.du);
  if (!(a11 > 0)) return;
  const double a12 = dot(d.dv, d.du) / a11;
  const double a22 = norm(d.dv - (a12 / a11) * d.du);
  if (!(a22 > 0)) return;
  a11_ = a11, a12_ = a12, a22_ = a22;
}

Vec2 WorkFrame::toWork(Vec2 uv) const {
  const double du = uv.u - origin_.u, dv = uv.v - origin_.v;
  return {a11_ * du + a12_ * dv, a22_ * dv};
}

Vec2 WorkFrame::toParam(Vec2 w) const {
  const double dv = w.v / a22_;
  const double du = (w.u - a12_ * dv) / a11_;
  return {origin_.u + du, origin_.v + dv};
}

SurfaceMetric::SurfaceMetric(const SurfaceGeometry& g, const WorkFrame& frame)
    : g_(g), frame_(frame) {
  const Vec2 origin = frame.toParam({0, 0});
  const Vec2 s1 = frame.toParam({1, 0}), s2 = frame.toParam({0, 1});
  axisU_ = {s1.u - origin.u, s1.v - origin.v};
  axisV_ = {s2.u - origin.u, s2.v - origin.v};
}

std::pair<Vec3, Vec3> SurfaceMetric::tangents(Vec2 work) const {
  const SurfaceDerivatives d = g_.firstDerivatives(frame_.toParam(work));
  return {axisU_.u * d.du + axisU_.v * d.dv, axisV_.u * d.du + axisV_.v * d.dv};
}

Metric2 SurfaceMetric::at(Vec2 work) const {
  const auto [t1, t2] = tangents(work);
  const Metric2 m{dot(t1, t1), dot(t1, t2), dot(t2, t2)};
  if (!(m.a > 0) || !(m.a * m.c - m.b * m.b > 0)) return {};  // singular point: Euclidean
  return m;
}

MetricFrame::MetricFrame(Metric2 m) {
  const double l11 = std::sqrt(m.a);
  const double l12 = m.b / l11;
  const double l22squared = m.c - l12 * l12;
  if (!(l11 > 0) || !(l22squared > 0)) return;
  l11_ = l11, l12_ = l12, l22_ = std::sqrt(l22squared);
}

}  // namespace geomesh
