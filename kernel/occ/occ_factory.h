#pragma once

#include <memory>

#include "kernel/geometry_factory.h"

namespace geomesh {

struct OccShapes;  // the shapes and their tags (kernel/occ/occ_factory.cpp)

// The OpenCASCADE geometry kernel (SetFactory("OpenCASCADE") in scripts). Shapes are built
// one call at a time; synchronize() exports them, with every vertex, edge, face and solid, to
// the Model with OpenCASCADE-backed geometry. OpenCASCADE itself stays behind this interface.
// So far it builds boxes, answers queries about its shapes and takes mesh sizes at their
// points; the other operations throw UnsupportedOperation.
class OccFactory final : public GeometryFactory {
 public:
  OccFactory();
  ~OccFactory();
  OccFactory(OccFactory&&) noexcept;
  OccFactory& operator=(OccFactory&&) noexcept;

  std::string name() const override { return "OpenCASCADE"; }

  // An axis-aligned box with a corner at `corner` and the opposite corner at corner + extent
  // (extents may be negative, not zero). tag < 0: the next free volume tag. Returns the tag.
  // Its 8 points, 12 curves and 6 surfaces get the next free tags of their dimensions.
  int addBox(int tag, Vec3 corner, Vec3 extent) override;

  double volume(int tag) const;  // of the volume `tag`; throws GeometryError if undefined
  int maxTag(int kind) const override;  // 0 when none, and for loops (none are kept)
  bool contains(EntityId e) const override;
  std::vector<int> tags(int dim) const override;
  Vec3 pointCoordinates(int tag) const override;  // throws GeometryError if undefined
  BoundingBox boundingBox(EntityId shape) const override;  // throws if undefined
  // Entities of `dim` whose bounding box is inside `box` (to 1e-8 of the box's diagonal).
  std::vector<int> entitiesInBox(int dim, const BoundingBox& box) const override;
  // Boundary{..}: as the built-in factory gives it (see GeoFactory::boundary): a curve's ends
  // in its direction, a surface's curves in loop order and a volume's surfaces in shell order,
  // as positive tags; combined: shared entities cancel, the others in ascending tags.
  std::vector<EntityId> boundary(const std::vector<EntityId>& shapes,
                                 bool combined) const override;
  // PointsOf{..}: the vertices of the shapes, once each, in OpenCASCADE's exploration order.
  std::vector<int> pointsOf(const std::vector<EntityId>& shapes) const override;
  // MeshSize{points} = size: the prescribed mesh size at those vertices.
  void setMeshSize(const std::vector<int>& points, double size) override;

  // Adds (or replaces) this factory's entities in the model; other entities are kept.
  void synchronize(Model& model) const override;
  void clear() override;

 private:
  std::unique_ptr<OccShapes> shapes_;
};

}  // namespace geomesh
