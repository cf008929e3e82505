// GeoFactory: the discrete entities of merged triangulations (surfaces as merged, and the
// points, curves and surfaces ClassifySurfaces finds), and the geometry CreateGeometry gives
// them.
#include "kernel/geo/geo_factory.h"

#include "kernel/geo/geo_detail.h"
#include "kernel/geo/polyline_geometry.h"

namespace geomesh {

using geo_detail::fail;
using geo_detail::requireNew;

void GeoFactory::addDiscreteSurface(int tag, const BoundingBox& box, const std::string& file,
                                    std::vector<std::vector<int>> loops) {
  requireNew(surfaces_, tag, "Surface");
  for (const std::vector<int>& loop : loops)
    for (int c : loop)
      if (!curves_.contains(std::abs(c)))
        fail("Surface ", tag, ": curve ", std::abs(c), " is not defined");
  surfaces_[tag] = Surface{tag, SurfaceKind::Discrete, std::move(loops)};
  discreteBoxes_[tag] = box;
  discreteFiles_[tag] = file;
  if (!box.empty()) {
    bounds_.include(box.min);
    bounds_.include(box.max);
  }
  noteTag(2, tag);
}

void GeoFactory::addDiscretePoint(int tag, Vec3 xyz) {
  addPoint(tag, xyz, 0);
  points_[tag].discrete = true;
  discretePoints_.insert(tag);
}

void GeoFactory::addDiscreteCurve(int tag, int startPoint, int endPoint, std::vector<Vec3> trace) {
  requireNew(curves_, tag, "Curve");
  for (int p : {startPoint, endPoint})
    if (!points_.contains(p)) fail("Curve ", tag, ": point ", p, " is not defined");
  if (trace.size() < 2) fail("Curve ", tag, ": a discrete curve needs two vertices or more");
  Curve c{tag, CurveKind::Other, {startPoint, endPoint}};
  c.trace = std::move(trace);
  curves_[tag] = std::move(c);
  noteTag(1, tag);
}

void GeoFactory::setDiscreteCurveGeometry(int tag) {
  const auto it = curves_.find(tag);
  if (it == curves_.end() || it->second.trace.empty())
    fail("CreateGeometry: curve ", tag, " is not a discrete curve");
  it->second.withGeometry = true;
}

void GeoFactory::setDiscreteSurfaceGeometry(int tag,
                                            std::shared_ptr<const SurfaceGeometry> geometry) {
  const auto it = surfaces_.find(tag);
  if (it == surfaces_.end() || it->second.kind != SurfaceKind::Discrete)
    fail("CreateGeometry: surface ", tag, " is not a discrete surface");
  it->second.discreteGeometry = std::move(geometry);
}

bool GeoFactory::isDiscrete(EntityId e) const {
  switch (e.dim) {
    case 0: return discretePoints_.contains(e.tag);
    case 1: {
      const auto it = curves_.find(e.tag);
      return it != curves_.end() && !it->second.trace.empty();
    }
    case 2: {
      const auto it = surfaces_.find(e.tag);
      return it != surfaces_.end() && it->second.kind == SurfaceKind::Discrete;
    }
    default: return false;
  }
}

}  // namespace geomesh
