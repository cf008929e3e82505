// repairCurvedElements: finds the curved elements whose Jacobian changes sign and makes them
// valid, by moving free high-order nodes or, failing that, by straightening them.
#pragma once

#include "kernel/messages.h"
#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_options.h"
#include "mesh/high_order/set_order.h"

namespace geomesh {

// With options.highOrderOptimize > 0, the elements whose scaled Jacobian is below
// options.highOrderThresholdMin, and the options.highOrderNumLayers layers around them, have
// their free high-order nodes (inside a volume, or inside a plane surface) moved by spreading
// the boundary's curvature inwards. Every element still invalid then has its high-order nodes
// put back on straight edges and faces, and so do the neighbours this makes invalid; a warning
// on `log` says how many. Counts go to `summary`.
void repairCurvedElements(const Model& model, const MeshOptions& options, Mesh& mesh,
                          MessageSink& log, HighOrderSummary& summary);

}  // namespace geomesh
