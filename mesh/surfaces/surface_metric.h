// WorkFrame, Metric2, SurfaceMetric and MetricFrame: lengths on a surface from its work plane.
#pragma once

#include <utility>

#include "kernel/geometry.h"

namespace geomesh {

// An affine map from a surface's parameter plane to a "work" plane whose lengths are those on
// the surface at a reference point (everywhere, for a plane). It keeps orientation:
// triangles counter-clockwise in the work plane are counter-clockwise in the parametrization.
class WorkFrame {
 public:
  WorkFrame(const SurfaceGeometry& g, Vec2 origin);
  Vec2 toWork(Vec2 uv) const;
  Vec2 toParam(Vec2 w) const;

 private:
  Vec2 origin_;
  double a11_ = 1, a12_ = 0, a22_ = 1;  // w = A (uv - origin), A upper triangular
};

// A symmetric positive definite 2x2 matrix [[a, b], [b, c]]: squared length of a work-plane
// vector d is a d.u^2 + 2 b d.u d.v + c d.v^2.
struct Metric2 {
  double a = 1, b = 0, c = 1;
};

// Lengths on a curved surface seen from its work plane: the first fundamental form of the
// surface at a work-plane point, expressed in work coordinates.
class SurfaceMetric {
 public:
  SurfaceMetric(const SurfaceGeometry& g, const WorkFrame& frame);
  Metric2 at(Vec2 work) const;
  // The surface's tangents along the work plane's two axes at a work-plane point: a
  // work-plane vector d is the surface vector d.u t1 + d.v t2 there.
  std::pair<Vec3, Vec3> tangents(Vec2 work) const;

 private:
  const SurfaceGeometry& g_;
  const WorkFrame& frame_;
  Vec2 axisU_, axisV_;  // parameter steps of unit work steps (the frame is affine)
};

// The linear map L with M = L^T L (Cholesky): lengths under M are Euclidean lengths after L.
class MetricFrame {
 public:
  MetricFrame() = default;  // the identity
  explicit MetricFrame(Metric2 m);
  Vec2 apply(Vec2 d) const { return {l11_ * d.u + l12_ * d.v, l22_ * d.v}; }
  Vec2 invert(Vec2 e) const {
    const double v = e.v / l22_;
    return {(e.u - l12_ * v) / l11_, v};
  }

 private:
  double l11_ = 1, l12_ = 0, l22_ = 1;
};

}  // namespace geomesh
