// BSplineGeometry (BSpline, Bezier) and CatmullRomGeometry (Spline) of the built-in kernel.
#pragma once

#include <vector>

#include "kernel/geometry.h"

namespace geomesh {

// A B-spline curve over [0, 1]: `knots` has points.size() + degree + 1 non-decreasing values
// and the curve is defined for t between knots[degree] and knots[points.size()], which the
// constructor maps onto [0, 1]. Clamped knots make it start and end at its end points.
// `kind` says how the script defined it: BSpline or Bezier.
class BSplineGeometry final : public CurveGeometry {
 public:
  BSplineGeometry(std::vector<Vec3> points, int degree, std::vector<double> knots,
                  CurveKind kind = CurveKind::BSpline);

  // The curves of the built-in kernel, all parametrized over [0, 1]:
  // BSpline: uniform clamped knots, degree 3 (lower when there are fewer than 4 points); a
  // closed control polygon (first point == last) gives a periodic uniform cubic instead.
  static BSplineGeometry uniform(std::vector<Vec3> points, bool closed);
  // Bezier: one polynomial piece of degree points.size() - 1.
  static BSplineGeometry bezier(std::vector<Vec3> points);

  Interval range() const override { return {0, 1}; }
  Vec3 point(double t) const override { return evaluate(t, 0); }
  Vec3 firstDerivative(double t) const override { return evaluate(t, 1); }
  Vec3 secondDerivative(double t) const override { return evaluate(t, 2); }
  CurveKind kind() const override { return kind_; }

 private:
  // The `order`-th derivative with respect to the [0, 1] parameter.
  Vec3 evaluate(double t, int order) const;

  std::vector<Vec3> points_;
  int degree_;
  std::vector<double> knots_;
  double start_, scale_;  // knot parameter = start_ + t * scale_
  CurveKind kind_;
};

// An interpolating (Catmull-Rom) spline through its points, one cubic piece between each two
// consecutive points, pieces of equal parameter length over [0, 1]. Beyond the ends the
// tangents come from mirrored points, or, for a closed chain (first point == last), from the
// points on the other side of the joint.
class CatmullRomGeometry final : public CurveGeometry {
 public:
  explicit CatmullRomGeometry(std::vector<Vec3> points);

  Interval range() const override { return {0, 1}; }
  Vec3 point(double t) const override { return evaluate(t, 0); }
  Vec3 firstDerivative(double t) const override { return evaluate(t, 1); }
  Vec3 secondDerivative(double t) const override { return evaluate(t, 2); }
  CurveKind kind() const override { return CurveKind::Spline; }

 private:
  Vec3 evaluate(double t, int order) const;
  Vec3 controlPoint(int i) const;  // i in -1 .. size: with the phantom points at the ends

  std::vector<Vec3> points_;
  bool closed_;
};

}  // namespace geomesh
