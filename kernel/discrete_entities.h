// DiscreteEntities: what the built-in factory holds of merged triangulations (STL, scans).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "kernel/bounding_box.h"
#include "kernel/geometry.h"
#include "kernel/model.h"

namespace geomesh {

// The discrete points, curves and surfaces of merged triangulations, as the built-in factory
// keeps them: surfaces as merged, then the corners, curves and patches ClassifySurfaces finds
// on them, then the geometry CreateGeometry gives them. None can be moved, copied or extruded.
class DiscreteEntities {
 public:
  virtual ~DiscreteEntities() = default;
  // A surface of a merged mesh file (`file`), lying in `box`, with its boundary curves
  // (signed, the outer loop first; none for a surface as merged).
  virtual void addDiscreteSurface(int tag, const BoundingBox& box, const std::string& file,
                                  std::vector<std::vector<int>> loops) = 0;
  virtual void addDiscretePoint(int tag, Vec3 xyz) = 0;
  // A curve along the triangulation's vertices `trace`, from the start point to the end one.
  virtual void addDiscreteCurve(int tag, int startPoint, int endPoint,
                                std::vector<Vec3> trace) = 0;
  // CreateGeometry: the curve's geometry becomes the polyline through its trace, the
  // surface's `geometry`; both are then meshed anew.
  virtual void setDiscreteCurveGeometry(int tag) = 0;
  virtual void setDiscreteSurfaceGeometry(int tag,
                                          std::shared_ptr<const SurfaceGeometry> geometry) = 0;
  virtual bool isDiscrete(EntityId e) const = 0;
  // A statement that changed the triangulations (ClassifySurfaces{..}; CreateGeometry;), for
  // the unrolled script to repeat after merging the file again.
  virtual void noteDiscreteStatement(std::string statement) = 0;
};

}  // namespace geomesh
