// The geometry of the built-in kernel's surfaces, and the Model built from its entities.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>

#include "kernel/geo/geo_factory.h"
#include "kernel/geo/circle_arc_geometry.h"
#include "kernel/geo/geo_detail.h"
#include "kernel/geo/swept_surface_geometry.h"
#include "kernel/plane_geometry.h"

namespace geomesh {

using geo_detail::fail;

std::vector<Vec3> GeoFactory::loopSamples(const std::vector<int>& curves) const {
  constexpr int kCurveSamples = 16;
  std::vector<Vec3> samples;
  for (int c : curves) {
    const Curve& curve = curves_.at(std::abs(c));
    samples.push_back(points_.at(curveEnds(c)[0]).xyz);
    if (curve.kind == CurveKind::Line && curve.points.size() == 2) continue;
    const auto geometry = curveGeometry(curve);
    for (int i = 1; i < kCurveSamples; ++i) {
      const double t = static_cast<double>(i) / kCurveSamples;
      samples.push_back(geometry->point(c >= 0 ? t : 1 - t));
    }
  }
  return samples;
}

namespace {

// The normal of the plane nearest to the points in the least-squares sense: the eigenvector of
// their covariance of smallest eigenvalue, found by inverse iteration from `guess` (Newell's
// normal, whose orientation it keeps). The guess stays when the points are exactly plane.
Vec3 leastSquaresNormal(const std::vector<Vec3>& xyz, Vec3 centroid, Vec3 guess) {
  double c[3][3] = {};
  for (Vec3 p : xyz) {
    const double d[3] = {p.x - centroid.x, p.y - centroid.y, p.z - centroid.z};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c[i][j] += d[i] * d[j];
  }
  auto column = [&](int j) { return Vec3{c[0][j], c[1][j], c[2][j]}; };
  const double det = dot(column(0), cross(column(1), column(2)));
  const double scale = c[0][0] + c[1][1] + c[2][2];
  if (!(std::abs(det) > 1e-30 * scale * scale * scale)) return guess;
  Vec3 n = guess;
  for (int step = 0; step < 20; ++step) {  // n <- C^-1 n by Cramer's rule, normalized
    const Vec3 a = column(0), b = column(1), e = column(2);
    const Vec3 next{dot(n, cross(b, e)) / det, dot(a, cross(n, e)) / det,
                    dot(a, cross(b, n)) / det};
    n = normalized(next);
  }
  return dot(n, guess) < 0 ? -1.0 * n : n;
}

}  // namespace

// The plane is fitted by least squares to the outer loop (its normal follows the loop's
// orientation, so that the loop runs counter-clockwise in the plane's parameters). Curved
// curves are sampled, so that the fit sees their shape. Loops that are only nearly plane
// are meshed on that plane: the deviation returned says how far they pass from it.
std::pair<std::shared_ptr<const SurfaceGeometry>, double> GeoFactory::fitPlaneSurface(
    int tag, const std::vector<std::vector<int>>& loops) const {
  const std::vector<Vec3> outer = loopSamples(loops.front());
  const PlaneFit fit = fitPlane(outer);
  if (norm(fit.normal) == 0) fail("Plane surface ", tag, ": its outer loop encloses no area");
  const Vec3 normal = leastSquaresNormal(outer, fit.origin, fit.normal);
  auto plane = std::make_shared<PlaneGeometry>(fit.origin, normal);
  double deviation = 0;
  for (const std::vector<int>& loop : loops)
    for (Vec3 xyz : loopSamples(loop)) {
      deviation = std::max(deviation, std::abs(dot(xyz - fit.origin, normal)));
      plane->include(xyz);
    }
  return {plane, deviation};
}

double GeoFactory::planeDeviation(int tag) const {
  const auto surface = surfaces_.find(tag);
  if (surface == surfaces_.end() || surface->second.kind != SurfaceKind::Plane) return 0;
  const double deviation = fitPlaneSurface(tag, surface->second.loops).second;
  return deviation > absoluteTolerance() ? deviation : 0;
}

namespace {

// The centre and radius shared by sides that are all circle arcs of one sphere, if they are.
std::optional<std::pair<Vec3, double>> commonSphere(
    const std::vector<CoonsSurfaceGeometry::Side>& sides, double tolerance) {
  std::optional<std::pair<Vec3, double>> sphere;
  for (const CoonsSurfaceGeometry::Side& side : sides) {
    const auto* arc = dynamic_cast<const CircleArcGeometry*>(side.curve.get());
    // A half circle's chord passes through the centre: no patch of the sphere follows from it.
    if (!arc || std::abs(arc->startRadius() - arc->endRadius()) > tolerance ||
        arc->angle() > 0.99 * std::acos(-1.0))
      return std::nullopt;
    if (!sphere) sphere.emplace(arc->center(), arc->startRadius());
    if (distance(arc->center(), sphere->first) > tolerance ||
        std::abs(arc->startRadius() - sphere->second) > tolerance)
      return std::nullopt;
  }
  return sphere;
}

}  // namespace

std::shared_ptr<const SurfaceGeometry> GeoFactory::surfaceGeometry(const Surface& s) const {
  // The sides and top of a boundary layer are where its mesh puts them: no geometry of theirs.
  if (s.sweep && s.sweep->kind == ExtrusionMotion::Kind::Normals) return nullptr;
  if (s.kind == SurfaceKind::Discrete) return s.discreteGeometry;  // null: its mesh is all
  if (s.kind == SurfaceKind::Plane) return fitPlaneSurface(s.tag, s.loops).first;
  const std::vector<int>& loop = s.loops.front();
  if (s.kind == SurfaceKind::Swept && s.sweep && s.extrusion) {
    const int source = s.extrusion->source;
    const bool reversed = std::find(loop.begin(), loop.end(), -source) != loop.end();
    if (auto curve = curves_.find(source); curve != curves_.end())
      return std::make_shared<SweptSurfaceGeometry>(curveGeometry(curve->second), *s.sweep,
                                                    reversed);
  }
  std::vector<CoonsSurfaceGeometry::Side> sides;
  for (int c : loop) sides.push_back({curveGeometry(curves_.at(std::abs(c))), c < 0});
  if (sides.size() != 3 && sides.size() != 4)
    fail("Surface ", s.tag, ": its loop has ", sides.size(),
         " curves; a non-plane surface needs 3 or 4");
  if (const auto sphere = commonSphere(sides, absoluteTolerance())) {
    std::vector<Vec3> corners;
    for (const CoonsSurfaceGeometry::Side& side : sides) {
      const Interval r = side.curve->range();
      corners.push_back(side.curve->point(side.reversed ? r.max : r.min));
    }
    return std::make_shared<SphericalPatchGeometry>(std::move(corners), sphere->first,
                                                    sphere->second);
  }
  return std::make_shared<CoonsSurfaceGeometry>(std::move(sides));
}


void GeoFactory::synchronize(Model& model) const {
  // A closed B-spline is periodic and passes through none of its control points: the point
  // that closes it is placed where the curve starts (and ends).
  std::map<int, std::shared_ptr<const CurveGeometry>> geometries;
  std::map<int, Vec3> closingPoints;
  for (const auto& [tag, c] : curves_) {
    auto geometry = curveGeometry(c);
    if (c.kind == CurveKind::BSpline && c.knots.empty() && c.points.size() >= 4 &&
        c.start() == c.end())
      closingPoints.emplace(c.start(), geometry->point(geometry->range().min));
    geometries.emplace(tag, std::move(geometry));
  }
  // A corner of a triangulation keeps the triangulation's node while a discrete curve without
  // geometry (whose mesh is the triangulation's edges) ends there.
  std::set<int> copiedCorners;
  for (const auto& [tag, c] : curves_)
    if (!c.trace.empty() && !c.withGeometry) copiedCorners.insert(c.points.begin(), c.points.end());
  for (const auto& [tag, p] : points_) {
    ModelPoint& point = model.addPoint(p);
    point.discrete = p.discrete && copiedCorners.contains(tag);
    if (auto moved = closingPoints.find(tag); moved != closingPoints.end())
      point.xyz = moved->second;
  }
  for (const auto& [tag, c] : curves_) {
    ModelCurve& curve = model.addCurve(ModelCurve{tag, c.start(), c.end(), geometries.at(tag)});
    curve.extrusion = c.extrusion;
    curve.periodic = c.periodic;
    curve.embeddedPoints = c.embeddedPoints;
    curve.compound = c.compound;
    curve.boxedByPoints = true;
    curve.discrete = !c.trace.empty() && !c.withGeometry;
  }
  for (const auto& [tag, s] : surfaces_) {
    ModelSurface surface{tag, s.loops, surfaceGeometry(s), s.embeddedPoints, s.embeddedCurves};
    surface.extrusion = s.extrusion;
    surface.periodic = s.periodic;
    surface.compound = s.compound;
    surface.discrete = s.kind == SurfaceKind::Discrete && !s.discreteGeometry;
    model.addSurface(std::move(surface));
  }
  for (const auto& [tag, v] : volumes_) {
    ModelVolume volume{tag, v.shells};
    volume.extrusion = v.extrusion;
    volume.embeddedPoints = v.embeddedPoints;
    volume.embeddedCurves = v.embeddedCurves;
    volume.embeddedSurfaces = v.embeddedSurfaces;
    model.addVolume(std::move(volume));
  }
  for (const auto& [id, group] : physicals_) {
    PhysicalGroup kept = group;
    const int dim = id.dim;
    std::erase_if(kept.entities, [&](int e) { return !model.contains({dim, std::abs(e)}); });
    model.addPhysicalGroup(std::move(kept));
  }
}

}  // namespace geomesh
