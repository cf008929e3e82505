// meshCurve, the 1D mesher, and the node chains of meshed points and curves.
#pragma once

#include <vector>

#include "kernel/model.h"
#include "mesh/sizes/size_field.h"
#include "mesh/core/mesh.h"
#include "mesh/sizes/size_rules.h"

namespace geomesh {

// Meshes one curve whose end points are already meshed (generateMesh's 0D stage). The target
// size varies linearly in arc length between the sizes of the end points (SizeRules); the
// curve gets as many segments as the integral of 1/size, rounded up unless within 1% above
// a whole number, and at least SizeRules::minimumSegments (3 when closed). Its nodes split that
// integral into equal parts. Adds the interior nodes with their parameters and target sizes
// (Mesh::setNodeSize) and the Line2 elements from start to end.
// With a background size field or Mesh.MeshSizeFromCurvature, the target size is the smallest
// of those bounds (Transfinite Curve constraints override all of them).
void meshCurve(const Model& model, const ModelCurve& curve, const SizeRules& rules, Mesh& mesh,
               const SizeFields* fields = nullptr);

// The node of a meshed model point; throws MeshError if the point has no mesh.
NodeIndex pointNode(const Mesh& mesh, int pointTag);

// The nodes of a meshed curve from start to end (both end points included), reversed when
// `signedTag` is negative.
// A degenerate curve (CurveGeometry::isDegenerate) has no segment: its chain is its vertex twice.
std::vector<NodeIndex> curveNodeChain(const Model& model, const Mesh& mesh, int signedTag);

// The curve parameters of curveNodeChain's nodes, in the same order; empty when the curve's
// nodes have none (a mesh made by copy rather than on the curve).
std::vector<double> curveNodeParameters(const Model& model, const Mesh& mesh, int signedTag);

}  // namespace geomesh
