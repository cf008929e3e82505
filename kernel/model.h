#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kernel/geometry.h"

namespace geomesh {

// Identifies a model entity: its dimension (0..3) and its tag within that dimension.
struct EntityId {
  int dim = 0;
  int tag = 0;
  friend auto operator<=>(const EntityId&, const EntityId&) = default;
};

struct ModelPoint {
  int tag = 0;
  Vec3 xyz;
  double meshSize = 0;  // 0: no size prescribed at this point
};

struct ModelCurve {
  int tag = 0;
  int startPoint = 0;  // tags of the bounding points (equal for a closed curve)
  int endPoint = 0;
  std::shared_ptr<const CurveGeometry> geometry;
};

struct ModelSurface {
  int tag = 0;
  // Curve loops: the first is the outer boundary, the others are holes. Signed curve tags: a
  // negative tag means the curve is followed from its end to its start.
  std::vector<std::vector<int>> loops;
  std::shared_ptr<const SurfaceGeometry> geometry;
  std::vector<int> embeddedPoints;
  std::vector<int> embeddedCurves;
};

struct ModelVolume {
  int tag = 0;
  // Surface loops (shells): the first is the outer one, the others are holes. Signed tags.
  std::vector<std::vector<int>> shells;
};

struct PhysicalGroup {
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> entities;  // tags of entities of dimension `dim`
};

struct BoundingBox {
  Vec3 min{1e300, 1e300, 1e300};
  Vec3 max{-1e300, -1e300, -1e300};
  bool empty() const { return min.x > max.x; }
  void include(Vec3 p);
  void include(const BoundingBox& b);
};

// The topological model: a boundary representation of points, curves, surfaces and volumes,
// with adjacencies both ways and physical groups. Geometry factories fill it on synchronize().
class Model {
 public:
  void clear();

  ModelPoint& addPoint(ModelPoint p);
  ModelCurve& addCurve(ModelCurve c);
  ModelSurface& addSurface(ModelSurface s);
  ModelVolume& addVolume(ModelVolume v);
  void addPhysicalGroup(PhysicalGroup g);

  const std::map<int, ModelPoint>& points() const { return points_; }
  const std::map<int, ModelCurve>& curves() const { return curves_; }
  const std::map<int, ModelSurface>& surfaces() const { return surfaces_; }
  const std::map<int, ModelVolume>& volumes() const { return volumes_; }
  // Ordered by (dim, tag).
  const std::map<EntityId, PhysicalGroup>& physicalGroups() const { return physicals_; }

  const ModelPoint* point(int tag) const;
  const ModelCurve* curve(int tag) const;
  const ModelSurface* surface(int tag) const;
  const ModelVolume* volume(int tag) const;
  bool contains(EntityId e) const;
  std::vector<EntityId> entities(int dim) const;  // ascending tags; dim -1: all
  int maxTag(int dim) const;

  // Boundary of an entity: signed tags of entities one dimension lower, in loop order.
  std::vector<int> boundary(EntityId e) const;
  // Entities one dimension higher whose boundary contains e (ascending tags).
  std::vector<int> upward(EntityId e) const;
  // Physical groups of dimension e.dim that contain e (ascending tags).
  std::vector<int> physicalTagsOf(EntityId e) const;

  BoundingBox boundingBox(EntityId e) const;
  BoundingBox boundingBox() const;

 private:
  std::map<int, ModelPoint> points_;
  std::map<int, ModelCurve> curves_;
  std::map<int, ModelSurface> surfaces_;
  std::map<int, ModelVolume> volumes_;
  std::map<EntityId, PhysicalGroup> physicals_;
  std::map<EntityId, std::vector<int>> upward_;  // maintained as entities are added
};

}  // namespace geomesh
