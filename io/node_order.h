// Node orders of foreign mesh formats, described by where each node lies on the element, and the
// edge lists those formats number their mid-edge nodes by.
#pragma once

#include <string_view>
#include <vector>

#include "mesh/core/element_type.h"

namespace geomesh {

// Where the nodes of an element lie, in a format's order: each place is the list of corners
// (vertex indices, numbered as in MSH) whose centre the node is at: one corner for a vertex,
// two for the middle of an edge, a face's corners for the centre of that face.
using NodePlaces = std::vector<std::vector<int>>;

// For each place, the index (in MSH order) of the node of `type` lying there: a writer puts
// element node result[k] at position k. Throws std::logic_error when no node lies at a place.
std::vector<int> mshNodesAt(ElementType type, const NodePlaces& places);

// The corners of the family in order, then `centres`: the layout most formats use.
NodePlaces cornersThen(ElementType type, const NodePlaces& centres);

// Edge lists by which formats number the middles of edges (corners numbered as in MSH).
NodePlaces triangleEdges();  // 01 12 20
NodePlaces quadEdges();      // 01 12 23 30
NodePlaces tetEdges();       // 01 12 20 03 13 23
// The bottom face's edges, then the top face's, then the vertical ones (Abaqus, VTK).
NodePlaces hexEdgesBottomTopVertical();
NodePlaces prismEdgesBottomTopVertical();
// The bottom face's edges, then the vertical ones, then the top face's (Nastran, CGNS).
NodePlaces hexEdgesBottomVerticalTop();
NodePlaces prismEdgesBottomVerticalTop();
NodePlaces pyramidEdges();  // the base's edges, then those to the apex

// "<format> output of <type> elements is not supported: <why>", as std::invalid_argument.
[[noreturn]] void refuseElementType(std::string_view format, ElementType type,
                                    std::string_view why);

}  // namespace geomesh
