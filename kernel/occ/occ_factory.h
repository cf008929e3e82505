#pragma once

#include <memory>

#include "kernel/model.h"

namespace geomesh {

struct OccShapes;  // the shapes and their tags (kernel/occ/occ_factory.cpp)

// The OpenCASCADE geometry kernel (SetFactory("OpenCASCADE") in scripts). Shapes are built
// one call at a time; synchronize() exports them, with every vertex, edge, face and solid, to
// the Model with OpenCASCADE-backed geometry. OpenCASCADE itself stays behind this interface.
class OccFactory {
 public:
  OccFactory();
  ~OccFactory();
  OccFactory(OccFactory&&) noexcept;
  OccFactory& operator=(OccFactory&&) noexcept;

  // An axis-aligned box with a corner at `corner` and the opposite corner at corner + extent
  // (extents may be negative, not zero). tag < 0: the next free volume tag. Returns the tag.
  // Its 8 points, 12 curves and 6 surfaces get the next free tags of their dimensions.
  int addBox(int tag, Vec3 corner, Vec3 extent);

  double volume(int tag) const;  // of the volume `tag`; throws GeometryError if undefined
  int maxTag(int dim) const;     // 0 when none

  // Adds (or replaces) this factory's entities in the model; other entities are kept.
  void synchronize(Model& model) const;
  void clear();

 private:
  std::unique_ptr<OccShapes> shapes_;
};

}  // namespace geomesh
