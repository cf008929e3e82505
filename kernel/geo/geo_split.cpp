// Split Curve (a curve cut into pieces at some of its own points) and Intersect Curve{..}
// Surface{..} (points where curves cross a surface), in the built-in kernel.
#include <algorithm>
#include <cstdlib>

#include "kernel/geo/geo_detail.h"
#include "kernel/geo/geo_factory.h"

namespace geomesh {

using geo_detail::fail;

namespace {

// The pieces of `points` between the cuts: each runs from one cut (or the first point) to the
// next (or the last point), sharing its end points with its neighbours.
std::vector<std::vector<int>> piecesBetween(const std::vector<int>& points,
                                            const std::vector<int>& cuts) {
  std::vector<std::vector<int>> pieces{{points.front()}};
  for (std::size_t i = 1; i < points.size(); ++i) {
    pieces.back().push_back(points[i]);
    const bool cut = std::find(cuts.begin(), cuts.end(), points[i]) != cuts.end();
    if (cut && i + 1 < points.size()) pieces.push_back({points[i]});
  }
  return pieces;
}

}  // namespace

std::vector<int> GeoFactory::splitCurve(int tag, const std::vector<int>& points) {
  const auto found = curves_.find(tag);
  if (found == curves_.end()) fail("Split Curve: curve ", tag, " is not defined");
  const Curve curve = found->second;
  const bool splittable =
      curve.knots.empty() && (curve.kind == CurveKind::Spline || curve.kind == CurveKind::BSpline ||
                              curve.kind == CurveKind::Bezier || curve.kind == CurveKind::Line);
  if (!splittable)
    fail("Split Curve: curve ", tag, " is not a spline or a line through points; only those split");
  std::vector<int> cuts;
  for (int p : points) cuts.push_back(std::abs(p));
  const auto pieces = piecesBetween(curve.points, cuts);
  if (pieces.size() == 1) return {tag};  // none of the points is inside the curve
  curves_.erase(tag);
  std::vector<int> tags;
  for (const std::vector<int>& piece : pieces) {
    const int pieceTag = maxTag(1) + 1;
    curves_[pieceTag] = Curve{pieceTag, curve.kind, piece};
    noteTag(1, pieceTag);
    tags.push_back(pieceTag);
  }
  replaceCurveInLoops(tag, tags);
  return tags;
}

// Every use of curve `tag` in a curve loop or a surface's loops becomes the chain of pieces
// (reversed where the curve was).
void GeoFactory::replaceCurveInLoops(int tag, const std::vector<int>& pieces) {
  auto replaceIn = [&](std::vector<int>& loop) {
    std::vector<int> replaced;
    for (int c : loop) {
      if (std::abs(c) != tag) {
        replaced.push_back(c);
        continue;
      }
      const std::vector<int> chain = c >= 0 ? pieces : geo_detail::reversedChain(pieces);
      replaced.insert(replaced.end(), chain.begin(), chain.end());
    }
    loop = std::move(replaced);
  };
  for (auto& [loopTag, loop] : curveLoops_) replaceIn(loop);
  for (auto& [surfaceTag, surface] : surfaces_)
    for (std::vector<int>& loop : surface.loops) replaceIn(loop);
}

namespace {

// The signed distance from the curve's point at t to the surface, along the surface's normal
// at the nearest point; nullopt where that nearest point is outside the surface's parameters.
struct SurfaceSide {
  const CurveGeometry& curve;
  const SurfaceGeometry& surface;

  double operator()(double t) const {
    const Vec3 p = curve.point(t);
    const Vec2 uv = surface.project(p);
    const SurfaceDerivatives d = surface.firstDerivatives(uv);
    const Vec3 n = cross(d.du, d.dv);
    const double length = norm(n);
    return length > 0 ? dot(p - surface.point(uv), n) / length : 0.0;
  }
};

// The parameters where the curve crosses the surface: sign changes between samples, refined
// by bisection.
std::vector<double> crossings(const CurveGeometry& curve, const SurfaceGeometry& surface) {
  constexpr int kSamples = 64;
  const SurfaceSide side{curve, surface};
  const Interval range = curve.range();
  std::vector<double> found;
  double t0 = range.min, f0 = side(t0);
  for (int i = 1; i <= kSamples; ++i) {
    const double t1 = range.min + (range.max - range.min) * i / kSamples, f1 = side(t1);
    if ((f0 < 0) != (f1 < 0) || f1 == 0) {
      double a = t0, b = t1, fa = f0;
      for (int step = 0; step < 60; ++step) {
        const double m = 0.5 * (a + b), fm = side(m);
        if ((fa < 0) == (fm < 0) && fm != 0) a = m, fa = fm;
        else b = m;
      }
      found.push_back(0.5 * (a + b));
    }
    t0 = t1, f0 = f1;
  }
  return found;
}

}  // namespace

std::vector<int> GeoFactory::intersectCurvesWithSurface(const std::vector<int>& curves,
                                                        int surface) {
  const auto host = surfaces_.find(std::abs(surface));
  if (host == surfaces_.end()) fail("Intersect: surface ", std::abs(surface), " is not defined");
  const auto shape = surfaceGeometry(host->second);
  const ParamBox box = shape->bounds();
  const double tolerance = absoluteTolerance();
  std::vector<int> made;
  for (int c : curves) {
    const auto curve = curves_.find(std::abs(c));
    if (curve == curves_.end()) fail("Intersect: curve ", std::abs(c), " is not defined");
    const auto geometry = curveGeometry(curve->second);
    for (double t : crossings(*geometry, *shape)) {
      const Vec3 p = geometry->point(t);
      const Vec2 uv = shape->project(p);
      const bool inside = uv.u >= box.u.min - tolerance && uv.u <= box.u.max + tolerance &&
                          uv.v >= box.v.min - tolerance && uv.v <= box.v.max + tolerance;
      if (!inside || distance(shape->point(uv), p) > 1e3 * tolerance) continue;
      const int tag = maxTag(0) + 1;
      addPoint(tag, p, 0);
      made.push_back(tag);
    }
  }
  return made;
}

}  // namespace geomesh
