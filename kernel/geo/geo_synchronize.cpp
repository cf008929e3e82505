// The geometry of the built-in kernel's surfaces, and the Model built from its entities.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
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
    if (curve.kind == CurveKind::Line) continue;
    const auto geometry = curveGeometry(curve);
    for (int i = 1; i < kCurveSamples; ++i) {
      const double t = static_cast<double>(i) / kCurveSamples;
      samples.push_back(geometry->point(c > 0 ? t : 1 - t));
    }
  }
  return samples;
}

// The plane is fitted to the outer loop (its normal follows the loop's orientation, so the
// loop runs counter-clockwise in the plane's parameters); every loop must lie on it. Curved
// curves are sampled, so that both the fit and the check see their shape.
std::shared_ptr<const SurfaceGeometry> GeoFactory::fitPlaneSurface(
    int tag, const std::vector<std::vector<int>>& loops) const {
  const PlaneFit fit = fitPlane(loopSamples(loops.front()));
  if (norm(fit.normal) == 0) fail("Plane surface ", tag, ": its outer loop encloses no area");
  auto plane = std::make_shared<PlaneGeometry>(fit.origin, fit.normal);
  const double tolerance = absoluteTolerance();
  for (std::size_t i = 0; i < loops.size(); ++i)
    for (Vec3 xyz : loopSamples(loops[i])) {
      const double offset = std::abs(dot(xyz - fit.origin, fit.normal));
      if (offset > tolerance)
        fail("Plane surface ", tag, " is not plane: its ",
             i == 0 ? "outer loop" : "hole " + std::to_string(i), " passes ", offset,
             " away from the plane of its outer loop");
      plane->include(xyz);
    }
  return plane;
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
  if (s.kind == SurfaceKind::Plane) return fitPlaneSurface(s.tag, s.loops);
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
  for (const auto& [tag, p] : points_) model.addPoint(p);
  for (const auto& [tag, c] : curves_) {
    ModelCurve& curve = model.addCurve(ModelCurve{tag, c.start(), c.end(), curveGeometry(c)});
    curve.extrusion = c.extrusion;
    curve.periodic = c.periodic;
    curve.embeddedPoints = c.embeddedPoints;
    curve.compound = c.compound;
  }
  for (const auto& [tag, s] : surfaces_) {
    ModelSurface surface{tag, s.loops, surfaceGeometry(s), s.embeddedPoints, s.embeddedCurves};
    surface.extrusion = s.extrusion;
    surface.periodic = s.periodic;
    surface.compound = s.compound;
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
