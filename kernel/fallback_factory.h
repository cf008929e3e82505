// A factory that hands what it does not support yet to another one, reporting each handover.
#pragma once

#include <functional>
#include <set>

#include "kernel/geometry_factory.h"

namespace geomesh {

// While a factory is incomplete (the OpenCASCADE one builds boxes only), scripts selecting it
// lose nothing: every operation goes to `primary` first, and when that throws
// UnsupportedOperation, to `fallback`, after telling the handover callback. Queries combine
// both (maxTag: the larger; contains: either; a point's coordinates: from its owner); mesh
// sizes, PointsOf and Boundary go to the factory holding each point or shape.
// Physical groups and Geometry.Tolerance live in the fallback, which synchronizes last, so
// that its groups may name entities of both.
class FallbackFactory final : public GeometryFactory {
 public:
  using Handover = std::function<void(const UnsupportedOperation&)>;
  FallbackFactory(GeometryFactory& primary, GeometryFactory& fallback)
      : primary_(primary), fallback_(fallback) {}
  void onHandover(Handover handover) { handover_ = std::move(handover); }

  std::string name() const override { return primary_.name(); }
  SolidModeling* solidModeling() override { return primary_.solidModeling(); }

  void addPoint(int tag, Vec3 xyz, double meshSize) override;
  void addLine(int tag, int startPoint, int endPoint) override;
  void addCircleArc(int tag, int startPoint, int centerPoint, int endPoint) override;
  void addEllipseArc(int tag, int startPoint, int centerPoint, int majorAxisPoint,
                     int endPoint) override;
  void addSpline(int tag, const std::vector<int>& points) override;
  void addBSpline(int tag, const std::vector<int>& points) override;
  void addBezier(int tag, const std::vector<int>& points) override;
  void addCircleArcAbout(int tag, int startPoint, int centerPoint, int endPoint,
                         Vec3 normal) override;
  void addPolyline(int tag, const std::vector<int>& points) override;
  void addNurbs(int tag, const std::vector<int>& points, const std::vector<double>& knots,
                int degree) override;
  std::vector<int> splitCurve(int tag, const std::vector<int>& points) override;
  double planeDeviation(int tag) const override;
  void coherePoints(const std::vector<int>& points) override;
  std::vector<int> intersectCurvesWithSurface(const std::vector<int>& curves,
                                              int surface) override;
  void addCurveLoop(int tag, std::vector<int> curves) override;
  void addPlaneSurface(int tag, std::vector<int> curveLoops) override;
  void addFillingSurface(int tag, std::vector<int> curveLoops,
                         const std::vector<int>& through) override;
  void addSurfaceLoop(int tag, std::vector<int> surfaces) override;
  void addVolume(int tag, std::vector<int> surfaceLoops) override;
  int addBox(int tag, Vec3 corner, Vec3 extent) override;

  void addPhysicalGroup(int dim, int tag, const std::string& name,
                        const std::vector<int>& entities) override;
  void removeFromPhysicalGroup(int dim, int tag, const std::vector<int>& entities) override;
  void clearPhysicalGroups() override;
  const std::map<EntityId, PhysicalGroup>& physicalGroups() const override;

  void setMeshSize(const std::vector<int>& points, double size) override;
  void addCompound(int dim, const std::vector<int>& tags) override;
  void embed(int dim, const std::vector<int>& tags, int hostDim, int hostTag) override;
  void setPeriodic(int dim, const std::vector<int>& slaves, const std::vector<int>& masters,
                   const AffineMap& map) override;
  void setPeriodicByCurves(int slave, const std::vector<int>& slaveCurves, int master,
                           const std::vector<int>& masterCurves) override;

  void transform(const std::vector<EntityId>& shapes, const AffineMap& map) override;
  std::vector<EntityId> duplicate(const std::vector<EntityId>& shapes) override;
  void remove(const std::vector<EntityId>& shapes, bool recursive) override;
  std::vector<EntityId> boundary(const std::vector<EntityId>& shapes,
                                 bool combined) const override;
  std::vector<EntityId> extrude(const std::vector<EntityId>& shapes,
                                const ExtrusionMotion& motion,
                                const ExtrusionLayers& layers) override;
  void coherence() override;

  int maxTag(int kind) const override;
  bool contains(EntityId e) const override;
  std::vector<int> tags(int dim) const override;
  Vec3 pointCoordinates(int tag) const override;
  std::vector<int> pointsOf(const std::vector<EntityId>& shapes) const override;
  BoundingBox boundingBox(EntityId shape) const override;
  std::vector<int> entitiesInBox(int dim, const BoundingBox& box) const override;

  void setTolerance(double relativeTolerance) override;
  double tolerance() const override;

  void synchronize(Model& model) const override;  // the primary's entities, then the fallback's
  void clear() override;                          // both
  // The fallback's definitions: the primary's are not written yet.
  void writeUnrolled(std::ostream& out, const UnrolledGeoHooks& hooks) const override;

 private:
  // Calls `op` on the primary factory, or on the fallback when the primary does not support it.
  template <class Op>
  decltype(auto) route(Op op) const;

  GeometryFactory& primary_;
  GeometryFactory& fallback_;
  Handover handover_;
  // Surface loops made of the fallback's surfaces alone (the discrete surfaces of a merged
  // mesh file, say): they, and the volumes they bound, are the fallback's.
  std::set<int> fallbackLoops_;
};

}  // namespace geomesh
