// Algebra of 2x2 metrics for anisotropic meshing: eigen sizes, intersection, restriction.
#pragma once

#include <array>
#include <cmath>

#include "kernel/vec3.h"
#include "mesh/surfaces/surface_metric.h"

namespace geomesh {

// The eigen decomposition of a metric: M = large e e' + small f f', f = e turned a quarter.
struct MetricEigen {
  double large = 1, small = 1;  // eigenvalues, large >= small
  Vec2 direction{1, 0};         // unit eigenvector of `large` (the direction of the smallest size)
};

MetricEigen eigen(Metric2 m);
Metric2 fromEigen(const MetricEigen& e);

// The metric of size h in every direction of the work plane (I / h^2).
Metric2 isotropicMetric(double h);
Metric2 scaled(Metric2 m, double factor);
// d' M d: the squared length of work-plane vector d.
double lengthSquared(Metric2 m, Vec2 d);
// Whether m is symmetric positive definite with finite entries.
bool isPositiveDefinite(Metric2 m);
// The arithmetic mean of three metrics.
Metric2 mean(Metric2 a, Metric2 b, Metric2 c);

// The largest metric asking for no size above either's in any direction (the intersection of
// their unit balls' inner ellipse): simultaneous reduction by the Cholesky factor of `a`.
Metric2 intersect(Metric2 a, Metric2 b);
// m = intersect(m, other); true if some direction's size went down by more than `tolerance`
// (relative, in squared lengths).
bool intersectInto(Metric2& m, Metric2 other, double tolerance);

// The metric seen from a frame F (M -> F^-T M F^-1): with F the Cholesky frame of the
// surface's first fundamental form, lengths under the result are in surface-length units per
// unit of the frame's Euclidean length, so its eigen sizes are sizes on the surface.
Metric2 inFrame(Metric2 m, const MetricFrame& f);
// The inverse of inFrame (M -> F' M F).
Metric2 outOfFrame(Metric2 m, const MetricFrame& f);

// Each eigen size h (1/sqrt(eigenvalue)) replaced by size(h), then the smaller eigen size
// raised, if needed, to at least the larger one over anisoMax.
template <class SizeMap>
Metric2 mapSizes(Metric2 m, SizeMap size, double anisoMax) {
  MetricEigen e = eigen(m);
  const double hSmall = size(1 / std::sqrt(e.large)), hLarge = size(1 / std::sqrt(e.small));
  e.large = 1 / (hSmall * hSmall);
  e.small = 1 / (hLarge * hLarge);
  if (anisoMax >= 1 && e.small * anisoMax * anisoMax < e.large)
    e.small = e.large / (anisoMax * anisoMax);
  return fromEigen(e);
}

// The 3D metric (xx, xy, xz, yy, yz, zz) restricted to the plane spanned by the tangents t1, t2
// (the surface's tangents along the work plane's axes): J' M J with J = [t1 t2].
Metric2 restrictMetric(const std::array<double, 6>& m, Vec3 t1, Vec3 t2);

// Metric gradation (Mesh.SmoothRatio): the metric's sizes carried along a work-plane vector d,
// growing by `rate` times their own value per unit of length, M / (1 + l rate)^2, with l the
// length of d under M. With rate = ratio - 1, the sizes at the ends of an edge of unit length
// differ by at most `ratio`.
Metric2 grownAlong(Metric2 m, Vec2 d, double rate);

}  // namespace geomesh
