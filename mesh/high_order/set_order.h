// setOrder: raises a first-order mesh to order 2, 3 or 4 (or lowers it back to 1), with the new
// nodes on the geometry, then makes sure no curved element is invalid.
#pragma once

#include <string>

#include "kernel/messages.h"
#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_options.h"

namespace geomesh {

// Highest order setOrder makes (lines, triangles, quadrangles, tetrahedra, hexahedra and
// pyramids; prisms stop at 2).
constexpr int kMaxElementOrder = 4;

struct HighOrderSummary {
  std::size_t nodesAdded = 0;
  std::size_t invalidFound = 0;   // curved elements whose Jacobian changed sign
  std::size_t repaired = 0;       // made valid by moving free high-order nodes
  std::size_t straightened = 0;   // made valid by straightening them
};

// Why `order` cannot be made, "" when it can: out of 1..kMaxElementOrder.
std::string unsupportedOrderReason(int order);

// Gives every element of `mesh` the order `options.elementOrder` (complete elements, or
// serendipity ones with options.secondOrderIncomplete), sharing each new node between the
// elements that share its edge or face. New nodes on a curve or a surface lie on its geometry
// unless options.secondOrderLinear. Curved elements whose Jacobian changes sign are repaired
// (options.highOrderOptimize) or straightened, with a warning on `log`. Throws MeshError for
// an element that cannot have the order (prisms above order 2).
HighOrderSummary setOrder(const Model& model, const MeshOptions& options, Mesh& mesh,
                          MessageSink& log);

}  // namespace geomesh
