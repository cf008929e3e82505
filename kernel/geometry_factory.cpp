// The operations a factory does not override (each throws UnsupportedOperation), and what
// factories share.
#include "kernel/geometry_factory.h"

#include <map>

namespace geomesh {

void GeometryFactory::unsupported(const std::string& operation) const {
  throw UnsupportedOperation(operation, name());
}

void GeometryFactory::addPoint(int, Vec3, double) { unsupported("Point"); }
void GeometryFactory::addLine(int, int, int) { unsupported("Line"); }
void GeometryFactory::addCircleArc(int, int, int, int) { unsupported("Circle"); }
void GeometryFactory::addEllipseArc(int, int, int, int, int) { unsupported("Ellipse"); }
void GeometryFactory::addSpline(int, const std::vector<int>&) { unsupported("Spline"); }
void GeometryFactory::addBSpline(int, const std::vector<int>&) { unsupported("BSpline"); }
void GeometryFactory::addBezier(int, const std::vector<int>&) { unsupported("Bezier"); }
void GeometryFactory::addCircleArcAbout(int, int, int, int, Vec3) { unsupported("Circle"); }
void GeometryFactory::addPolyline(int, const std::vector<int>&) { unsupported("Line"); }
void GeometryFactory::addNurbs(int, const std::vector<int>&, const std::vector<double>&, int) {
  unsupported("Nurbs");
}
std::vector<int> GeometryFactory::splitCurve(int, const std::vector<int>&) {
  unsupported("Split Curve");
}
double GeometryFactory::planeDeviation(int) const { return 0; }
void GeometryFactory::coherePoints(const std::vector<int>&) { unsupported("Coherence Point"); }
std::vector<int> GeometryFactory::intersectCurvesWithSurface(const std::vector<int>&, int) {
  unsupported("Intersect");
}
void GeometryFactory::addCurveLoop(int, std::vector<int>) { unsupported("Curve Loop"); }
void GeometryFactory::addPlaneSurface(int, std::vector<int>) { unsupported("Plane Surface"); }
void GeometryFactory::addFillingSurface(int, std::vector<int>, const std::vector<int>&) {
  unsupported("Surface");
}
void GeometryFactory::addSurfaceLoop(int, std::vector<int>) { unsupported("Surface Loop"); }
void GeometryFactory::addVolume(int, std::vector<int>) { unsupported("Volume"); }
int GeometryFactory::addBox(int, Vec3, Vec3) { unsupported("Box"); }

void GeometryFactory::addPhysicalGroup(int, int, const std::string&, const std::vector<int>&) {
  unsupported("Physical");
}
void GeometryFactory::removeFromPhysicalGroup(int, int, const std::vector<int>&) {
  unsupported("Physical");
}
void GeometryFactory::clearPhysicalGroups() { unsupported("Delete Physicals"); }
const std::map<EntityId, PhysicalGroup>& GeometryFactory::physicalGroups() const {
  unsupported("Physical");
}

void GeometryFactory::setMeshSize(const std::vector<int>&, double) { unsupported("MeshSize"); }
void GeometryFactory::addCompound(int, const std::vector<int>&) { unsupported("Compound"); }
void GeometryFactory::embed(int, const std::vector<int>&, int, int) { unsupported("In"); }
void GeometryFactory::setPeriodic(int, const std::vector<int>&, const std::vector<int>&,
                                  const AffineMap&) {
  unsupported("Periodic");
}
void GeometryFactory::setPeriodicByCurves(int, const std::vector<int>&, int,
                                          const std::vector<int>&) {
  unsupported("Periodic");
}

void GeometryFactory::transform(const std::vector<EntityId>&, const AffineMap&) {
  unsupported("transformation");
}
std::vector<EntityId> GeometryFactory::duplicate(const std::vector<EntityId>&) {
  unsupported("Duplicata");
}
void GeometryFactory::remove(const std::vector<EntityId>&, bool) { unsupported("Delete"); }
std::vector<EntityId> GeometryFactory::boundary(const std::vector<EntityId>&, bool) const {
  unsupported("Boundary");
}
std::vector<EntityId> GeometryFactory::extrude(const std::vector<EntityId>&,
                                               const ExtrusionMotion&, const ExtrusionLayers&) {
  unsupported("Extrude");
}
void GeometryFactory::coherence() { unsupported("Coherence"); }

Vec3 GeometryFactory::pointCoordinates(int) const { unsupported("Point{..}"); }
std::vector<int> GeometryFactory::pointsOf(const std::vector<EntityId>&) const {
  unsupported("PointsOf");
}
BoundingBox GeometryFactory::boundingBox(EntityId) const { unsupported("BoundingBox"); }
std::vector<int> GeometryFactory::entitiesInBox(int, const BoundingBox&) const {
  unsupported("In BoundingBox");
}

void GeometryFactory::setTolerance(double) { unsupported("Geometry.Tolerance"); }
double GeometryFactory::tolerance() const { unsupported("Geometry.Tolerance"); }

void GeometryFactory::writeUnrolled(std::ostream&, const UnrolledGeoHooks&) const {
  unsupported("geo_unrolled");
}

std::vector<EntityId> cancelShared(const std::vector<EntityId>& boundaries) {
  std::map<EntityId, int> count;
  for (EntityId e : boundaries) ++count[e];
  std::vector<EntityId> kept;
  for (const auto& [e, n] : count)
    if (n == 1) kept.push_back(e);
  return kept;
}

}  // namespace geomesh
