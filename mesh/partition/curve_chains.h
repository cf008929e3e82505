// Chains of line elements: the connected runs of a curve piece, each in walking order.
#pragma once

#include <functional>
#include <vector>

#include "mesh/core/mesh.h"

namespace geomesh {

// The lines of `block` grouped into chains: lines are linked through a corner node for which
// `joins` is true (a node inside the curve, not one of its points). With `walk`, each chain
// lists its lines from one end to the other, every line turned to follow the walk (a closed
// chain starts at its lowest line); without, the lines keep their order and direction (lines
// of a model curve, already in its order). Returns a block per chain.
std::vector<ElementBlock> splitIntoChains(const ElementBlock& block,
                                          const std::function<bool(NodeIndex)>& joins,
                                          bool walk = true);

// Lines of one curve put in order from the line leaving `start`, each following the one
// before; false (and `block` unchanged) when they do not make one such chain.
bool orderAlongCurve(ElementBlock& block, NodeIndex start);

}  // namespace geomesh
