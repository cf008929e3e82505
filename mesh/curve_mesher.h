#pragma once

#include <vector>

#include "kernel/model.h"
#include "mesh/fields/size_field.h"
#include "mesh/mesh.h"
#include "mesh/size_rules.h"

namespace geomesh {

// Meshes one curve whose end points are already meshed (generateMesh's 0D stage). The target
// size varies linearly in arc length between the sizes of the end points (SizeRules); the
// curve gets as many segments as the integral of 1/size, rounded up unless within 1% above
// a whole number; at least 1, 3 when closed, and 6 per full turn of its tangent (a circular
// arc of angle a gets at least 6a/2pi). Its nodes split that integral into equal parts. Adds the
// interior nodes with their parameters and the Line2 elements from start to end; nodeSizes (indexed
// by node) receives the target size at each new node.
// With a background size field, the target size is the smaller of the two (Transfinite
// Curve constraints override both).
void meshCurve(const Model& model, const ModelCurve& curve, const SizeRules& rules, Mesh& mesh,
               std::vector<double>& nodeSizes, const SizeFields* fields = nullptr);

// The node of a meshed model point; throws MeshError if the point has no mesh.
NodeIndex pointNode(const Mesh& mesh, int pointTag);

// The nodes of a meshed curve from start to end (both end points included), reversed when
// `signedTag` is negative.
std::vector<NodeIndex> curveNodeChain(const Model& model, const Mesh& mesh, int signedTag);

}  // namespace geomesh
