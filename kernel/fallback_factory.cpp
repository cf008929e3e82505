// Each operation of the fallback factory: to the primary factory, else to the fallback.
#include "kernel/fallback_factory.h"

#include <algorithm>
#include <cstdlib>

namespace geomesh {

template <class Op>
decltype(auto) FallbackFactory::route(Op op) const {
  try {
    return op(primary_);
  } catch (const UnsupportedOperation& unsupported) {
    if (handover_) handover_(unsupported);
  }
  return op(fallback_);
}

void FallbackFactory::addPoint(int tag, Vec3 xyz, double meshSize) {
  route([&](GeometryFactory& f) { f.addPoint(tag, xyz, meshSize); });
}
void FallbackFactory::addLine(int tag, int startPoint, int endPoint) {
  route([&](GeometryFactory& f) { f.addLine(tag, startPoint, endPoint); });
}
void FallbackFactory::addCircleArc(int tag, int startPoint, int centerPoint, int endPoint) {
  route([&](GeometryFactory& f) { f.addCircleArc(tag, startPoint, centerPoint, endPoint); });
}
void FallbackFactory::addEllipseArc(int tag, int startPoint, int centerPoint, int majorAxisPoint,
                                    int endPoint) {
  route([&](GeometryFactory& f) {
    f.addEllipseArc(tag, startPoint, centerPoint, majorAxisPoint, endPoint);
  });
}
void FallbackFactory::addSpline(int tag, const std::vector<int>& points) {
  route([&](GeometryFactory& f) { f.addSpline(tag, points); });
}
void FallbackFactory::addBSpline(int tag, const std::vector<int>& points) {
  route([&](GeometryFactory& f) { f.addBSpline(tag, points); });
}
void FallbackFactory::addBezier(int tag, const std::vector<int>& points) {
  route([&](GeometryFactory& f) { f.addBezier(tag, points); });
}
void FallbackFactory::addCircleArcAbout(int tag, int startPoint, int centerPoint, int endPoint,
                                        Vec3 normal) {
  route([&](GeometryFactory& f) {
    f.addCircleArcAbout(tag, startPoint, centerPoint, endPoint, normal);
  });
}
void FallbackFactory::addPolyline(int tag, const std::vector<int>& points) {
  route([&](GeometryFactory& f) { f.addPolyline(tag, points); });
}
void FallbackFactory::addNurbs(int tag, const std::vector<int>& points,
                               const std::vector<double>& knots, int degree) {
  route([&](GeometryFactory& f) { f.addNurbs(tag, points, knots, degree); });
}
std::vector<int> FallbackFactory::splitCurve(int tag, const std::vector<int>& points) {
  return route([&](GeometryFactory& f) { return f.splitCurve(tag, points); });
}
std::vector<int> FallbackFactory::intersectCurvesWithSurface(const std::vector<int>& curves,
                                                             int surface) {
  return route([&](GeometryFactory& f) { return f.intersectCurvesWithSurface(curves, surface); });
}
void FallbackFactory::coherePoints(const std::vector<int>& points) {
  route([&](GeometryFactory& f) { f.coherePoints(points); });
}
double FallbackFactory::planeDeviation(int tag) const {
  return std::max(primary_.planeDeviation(tag), fallback_.planeDeviation(tag));
}
void FallbackFactory::addCurveLoop(int tag, std::vector<int> curves) {
  route([&](GeometryFactory& f) { f.addCurveLoop(tag, curves); });
}
void FallbackFactory::addPlaneSurface(int tag, std::vector<int> curveLoops) {
  route([&](GeometryFactory& f) { f.addPlaneSurface(tag, curveLoops); });
}
void FallbackFactory::addFillingSurface(int tag, std::vector<int> curveLoops,
                                        const std::vector<int>& through) {
  route([&](GeometryFactory& f) { f.addFillingSurface(tag, curveLoops, through); });
}
void FallbackFactory::addSurfaceLoop(int tag, std::vector<int> surfaces) {
  auto fallbacks = [&](int s) {
    return fallback_.contains({2, std::abs(s)}) && !primary_.contains({2, std::abs(s)});
  };
  const bool theFallbacks =
      !surfaces.empty() && std::all_of(surfaces.begin(), surfaces.end(), fallbacks);
  if (theFallbacks) {
    fallback_.addSurfaceLoop(tag, std::move(surfaces));
    fallbackLoops_.insert(tag);
    return;
  }
  route([&](GeometryFactory& f) { f.addSurfaceLoop(tag, surfaces); });
}
void FallbackFactory::addVolume(int tag, std::vector<int> surfaceLoops) {
  auto fallbacks = [&](int l) { return fallbackLoops_.contains(std::abs(l)); };
  const bool theFallbacks =
      !surfaceLoops.empty() && std::all_of(surfaceLoops.begin(), surfaceLoops.end(), fallbacks);
  if (theFallbacks) return fallback_.addVolume(tag, std::move(surfaceLoops));
  route([&](GeometryFactory& f) { f.addVolume(tag, surfaceLoops); });
}
int FallbackFactory::addBox(int tag, Vec3 corner, Vec3 extent) {
  return route([&](GeometryFactory& f) { return f.addBox(tag, corner, extent); });
}

void FallbackFactory::addPhysicalGroup(int dim, int tag, const std::string& name,
                                       const std::vector<int>& entities) {
  fallback_.addPhysicalGroup(dim, tag, name, entities);
}
void FallbackFactory::removeFromPhysicalGroup(int dim, int tag,
                                              const std::vector<int>& entities) {
  fallback_.removeFromPhysicalGroup(dim, tag, entities);
}
void FallbackFactory::clearPhysicalGroups() { fallback_.clearPhysicalGroups(); }
const std::map<EntityId, PhysicalGroup>& FallbackFactory::physicalGroups() const {
  return fallback_.physicalGroups();
}

// The primary's points get their size from the primary, the others from the fallback.
void FallbackFactory::setMeshSize(const std::vector<int>& points, double size) {
  std::vector<int> primaryPoints, others;
  for (int p : points) (primary_.contains({0, p}) ? primaryPoints : others).push_back(p);
  if (!primaryPoints.empty())
    route([&](GeometryFactory& f) { f.setMeshSize(primaryPoints, size); });
  if (!others.empty() || points.empty()) fallback_.setMeshSize(others, size);
}
void FallbackFactory::addCompound(int dim, const std::vector<int>& tags) {
  route([&](GeometryFactory& f) { f.addCompound(dim, tags); });
}
void FallbackFactory::embed(int dim, const std::vector<int>& tags, int hostDim, int hostTag) {
  route([&](GeometryFactory& f) { f.embed(dim, tags, hostDim, hostTag); });
}
void FallbackFactory::setPeriodic(int dim, const std::vector<int>& slaves,
                                  const std::vector<int>& masters, const AffineMap& map) {
  route([&](GeometryFactory& f) { f.setPeriodic(dim, slaves, masters, map); });
}
void FallbackFactory::setPeriodicByCurves(int slave, const std::vector<int>& slaveCurves,
                                          int master, const std::vector<int>& masterCurves) {
  route([&](GeometryFactory& f) {
    f.setPeriodicByCurves(slave, slaveCurves, master, masterCurves);
  });
}

void FallbackFactory::transform(const std::vector<EntityId>& shapes, const AffineMap& map) {
  route([&](GeometryFactory& f) { f.transform(shapes, map); });
}
std::vector<EntityId> FallbackFactory::duplicate(const std::vector<EntityId>& shapes) {
  return route([&](GeometryFactory& f) { return f.duplicate(shapes); });
}
void FallbackFactory::remove(const std::vector<EntityId>& shapes, bool recursive) {
  route([&](GeometryFactory& f) { f.remove(shapes, recursive); });
}
// Each shape's boundary comes from the factory that holds it.
std::vector<EntityId> FallbackFactory::boundary(const std::vector<EntityId>& shapes,
                                                bool combined) const {
  std::vector<EntityId> out;
  for (EntityId shape : shapes) {
    const EntityId positive{shape.dim, shape.tag < 0 ? -shape.tag : shape.tag};
    const std::vector<EntityId> more =
        primary_.contains(positive)
            ? route([&](GeometryFactory& f) { return f.boundary({shape}, false); })
            : fallback_.boundary({shape}, false);
    out.insert(out.end(), more.begin(), more.end());
  }
  return combined ? cancelShared(out) : out;
}
std::vector<EntityId> FallbackFactory::extrude(const std::vector<EntityId>& shapes,
                                               const ExtrusionMotion& motion,
                                               const ExtrusionLayers& layers) {
  return route([&](GeometryFactory& f) { return f.extrude(shapes, motion, layers); });
}
void FallbackFactory::coherence() {
  route([&](GeometryFactory& f) { f.coherence(); });
}

int FallbackFactory::maxTag(int kind) const {
  return std::max(primary_.maxTag(kind), fallback_.maxTag(kind));
}
bool FallbackFactory::contains(EntityId e) const {
  return primary_.contains(e) || fallback_.contains(e);
}
std::vector<int> FallbackFactory::tags(int dim) const {
  std::vector<int> tags = primary_.tags(dim);
  const std::vector<int> more = fallback_.tags(dim);
  tags.insert(tags.end(), more.begin(), more.end());
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}
Vec3 FallbackFactory::pointCoordinates(int tag) const {
  return primary_.contains({0, tag}) ? primary_.pointCoordinates(tag)
                                     : fallback_.pointCoordinates(tag);
}
// Each shape's points come from the factory that holds it.
std::vector<int> FallbackFactory::pointsOf(const std::vector<EntityId>& shapes) const {
  std::vector<int> points;
  for (EntityId shape : shapes) {
    const EntityId positive{shape.dim, shape.tag < 0 ? -shape.tag : shape.tag};
    const std::vector<int> more =
        primary_.contains(positive)
            ? route([&](GeometryFactory& f) { return f.pointsOf({shape}); })
            : fallback_.pointsOf({shape});
    for (int p : more)
      if (std::find(points.begin(), points.end(), p) == points.end()) points.push_back(p);
  }
  return points;
}
BoundingBox FallbackFactory::boundingBox(EntityId shape) const {
  const EntityId positive{shape.dim, shape.tag < 0 ? -shape.tag : shape.tag};
  return primary_.contains(positive) ? primary_.boundingBox(shape)
                                      : fallback_.boundingBox(shape);
}
// Those of both factories, in ascending tags.
std::vector<int> FallbackFactory::entitiesInBox(int dim, const BoundingBox& box) const {
  std::vector<int> tags = fallback_.entitiesInBox(dim, box);
  try {
    const std::vector<int> more = primary_.entitiesInBox(dim, box);
    tags.insert(tags.end(), more.begin(), more.end());
  } catch (const UnsupportedOperation&) {
    // the fallback's entities are all there is to find
  }
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

void FallbackFactory::setTolerance(double relativeTolerance) {
  fallback_.setTolerance(relativeTolerance);
}
double FallbackFactory::tolerance() const { return fallback_.tolerance(); }

void FallbackFactory::synchronize(Model& model) const {
  primary_.synchronize(model);
  fallback_.synchronize(model);
}
void FallbackFactory::clear() {
  primary_.clear();
  fallback_.clear();
  fallbackLoops_.clear();
}
void FallbackFactory::writeUnrolled(std::ostream& out, const UnrolledGeoHooks& hooks) const {
  fallback_.writeUnrolled(out, hooks);
}

}  // namespace geomesh
