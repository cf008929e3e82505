// Layer columns in the plane: their directions and heights at each wall node, fans at convex
// corners, and their shortening where they would cross.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/sizes/boundary_layer_field.h"

namespace geomesh {

// One closed loop of a plane surface's boundary, in an orthonormal frame of the plane: its
// nodes in loop order (the first not repeated), the model point at each node (0: none) and
// the layer asked for on each segment i -> i+1 (nullptr: none).
struct LayerWall {
  std::vector<Vec2> xy;
  std::vector<int> point;
  std::vector<const BoundaryLayerParameters*> layer;
  bool domainLeft = true;  // the surface lies left of the loop's direction
};

// A column of layer points from a wall node: point k (k >= 1) at base + heights[k-1] direction;
// `levels` of them are kept (fewer than heights.size() where the column was shortened).
struct LayerColumn {
  Vec2 base;
  Vec2 direction;
  std::vector<double> heights;
  std::size_t levels = 0;
  Vec2 at(std::size_t k) const;  // k in [0, levels]: 0 is the base
};

// The columns of each node of a wall: none (no layer there), one, or the F + 1 columns of a
// fan of F elements, in loop order.
using WallColumns = std::vector<std::vector<LayerColumn>>;

// The columns of a wall: at each node whose two segments both carry a layer (nodes where a
// layer meets a segment without one get none, and neither does a node left alone between
// two such ends). At a convex corner that is in the layer's FanPointsList, a fan of its
// FanPointsSizesList count of elements (else `fanElements`); elsewhere one column along the
// bisector of the two segments' normals, its heights stretched by 1/cos of half the turn (at
// most twice) so that its points lie where the layers of both sides meet.
WallColumns layerColumns(const LayerWall& wall, int fanElements);

// A cell of a layer between two neighbouring columns a and b (b after a along the wall), at
// `level` (from point level to level + 1 on each side; a column shorter than the level
// contributes its top).
struct LayerCell {
  std::size_t node;  // of column a
  std::size_t a, b;  // positions of the columns in their node's list; b of node + 1 when
                     // `acrossSegment`
  bool acrossSegment;
  std::size_t level;
};
void forEachCell(const LayerWall& wall, const WallColumns& columns,
                 const std::function<void(const LayerCell&)>& visit);

// The corners of a cell (3 or 4 after merging repeated points), in the wall's direction:
// counter-clockwise when the surface lies left of the wall.
std::vector<Vec2> cellCorners(const LayerWall& wall, const WallColumns& columns,
                              const LayerCell& cell);

// Shortens the columns so that none reaches further than 0.45 of the way to a wall segment
// that does not touch it (facing layers then stop short of each other), none makes an
// inverted or non-convex cell with its neighbours, and no two cells overlap (the layers of
// two walls meeting at a concave corner, where the columns near it run alongside the other
// wall's layer). Returns the bases of the shortened columns.
std::vector<Vec2> limitColumns(std::span<const LayerWall> walls, std::span<WallColumns> columns);

}  // namespace geomesh
