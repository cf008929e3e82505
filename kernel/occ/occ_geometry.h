#pragma once

// Curve and surface evaluators over OpenCASCADE edges and faces. Only kernel/occ/*.cpp include
// this header; it names the OpenCASCADE types without including their headers.

#include <memory>

#include "kernel/geometry.h"

class TopoDS_Edge;
class TopoDS_Face;

namespace geomesh {

std::shared_ptr<const CurveGeometry> makeOccCurve(const TopoDS_Edge& edge);
// Parameters are those of the face's underlying surface; bounds are the face's.
std::shared_ptr<const SurfaceGeometry> makeOccSurface(const TopoDS_Face& face);

}  // namespace geomesh
