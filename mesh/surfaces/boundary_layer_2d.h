// buildSurfaceLayer: the 2D boundary layer of a plane surface along its layer curves.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/sizes/boundary_layer_field.h"
#include "mesh/sizes/size_field.h"

namespace geomesh {

// What a surface's boundary layer leaves to the unstructured mesher: the fronts (closed
// cycles of nodes, the first not repeated, with their parameters) bounding the rest of the
// surface, and the layer's own elements, counter-clockwise in the surface's parametrization.
struct SurfaceLayer {
  std::vector<std::vector<NodeIndex>> fronts;
  std::vector<std::vector<Vec2>> frontParameters;
  std::vector<std::vector<double>> frontSizes;  // target size at each front node
  std::vector<NodeIndex> quadrangles;           // 4 nodes each
  std::vector<NodeIndex> triangles;             // 3 nodes each
};

// Builds the layer of the BoundaryLayer fields `layers` in `surface`, when some of its
// boundary curves are in a field's CurvesList (and the surface is not in its
// ExcludedSurfacesList): at each mesh node inside a run of layer curves, a column of nodes
// along the normal into the surface at the field's heights; at a convex corner in
// FanPointsList, a fan of `fanElements` (Mesh.BoundaryLayerFanElements) elements unless
// FanPointsSizesList says otherwise; at other corners one column along the bisector. The
// layer stops one node short of where a layer curve meets a curve without layer. Columns are
// shortened where they would reach another wall or cross their neighbours, with a warning
// naming the place. The column nodes are added to `mesh` and to `em` (the surface's mesh, with
// their parameters). nullopt when no layer applies; a surface that is not plane gets none,
// with a warning.
std::optional<SurfaceLayer> buildSurfaceLayer(
    const Model& model, const ModelSurface& surface,
    std::span<const BoundaryLayerParameters* const> layers, int fanElements,
    const SizeFields& fields, Mesh& mesh, EntityMesh& em);

}  // namespace geomesh
