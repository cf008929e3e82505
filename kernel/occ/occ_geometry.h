// Curve and surface evaluators over OpenCASCADE edges and faces, without its headers.
#pragma once

// Curve and surface evaluators over OpenCASCADE edges and faces. Only kernel/occ/*.cpp include
// this header; it names the OpenCASCADE types without including their headers.

#include <functional>
#include <memory>

#include "kernel/geometry.h"

class TopoDS_Edge;
class TopoDS_Face;

namespace geomesh {

std::shared_ptr<const CurveGeometry> makeOccCurve(const TopoDS_Edge& edge);
// The tag of a face's edge (the edge as the face uses it: its orientation gives the sign).
using OccEdgeTag = std::function<int(const TopoDS_Edge&)>;

// Parameters are those of the face's underlying surface; bounds are the face's. With
// `edgeTag`, the surface answers curveParameters() for its edges from their curves on the
// face (for a seam, one per orientation).
std::shared_ptr<const SurfaceGeometry> makeOccSurface(const TopoDS_Face& face,
                                                      const OccEdgeTag& edgeTag = {});

}  // namespace geomesh
