// Shape healing of the OpenCASCADE factory, for HealShapes and for the files it reads.
#pragma once

#include <TopoDS_Shape.hxx>

#include "kernel/solid_modeling.h"

namespace geomesh {

// `shape` healed as the options say: degenerated edges and faces repaired, small edges and
// small (spot and strip) faces removed, free faces sewn into shells, closed shells made
// solids. Solids, and shapes sewing leaves alone, are kept. Throws Standard_Failure.
TopoDS_Shape healedShape(const TopoDS_Shape& shape, const SolidModeling::HealingOptions& options);

}  // namespace geomesh
