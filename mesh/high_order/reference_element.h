// ReferenceElement: where each node of an element type sits on the reference element, in the
// node order of MSH files, and on which vertex, edge, face or interior it lies.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/core/element_type.h"

namespace geomesh {

// Where one node lies: on a vertex, an edge, a face (the element itself for a triangle or a
// quadrangle) or inside a volume element. On an edge or a face the node is the point of the
// sub-entity's lattice whose integer weights on the sub-entity's corners are `weights`
// (barycentric on edges and triangles, bilinear on quadrangles; they add up to `total`). Two
// elements sharing a sub-entity name the same node by the same corners and weights.
struct NodePlace {
  enum Kind : std::uint8_t { Vertex, Edge, Face, Cell };
  Kind kind = Vertex;
  std::uint8_t cornerCount = 0;
  std::array<std::uint8_t, 4> corners{};   // element vertex indices
  std::array<std::uint16_t, 4> weights{};  // one per corner
  std::uint16_t total = 1;
};

struct ReferenceElement {
  ElementType type{};
  ElementFamily family{};
  int order = 1;
  // Reference coordinates of each node (unused components 0): lines on [-1, 1], triangles and
  // tetrahedra on the unit simplex, quadrangles and hexahedra on [-1, 1]^d, prisms on the unit
  // triangle times [-1, 1], pyramids on the square [-1, 1]^2 at z = 0 with their apex at z = 1.
  std::vector<std::array<double, 3>> xi;
  std::vector<NodePlace> places;
};

// Built on first use and kept; safe to call from several threads.
const ReferenceElement& referenceElement(ElementType type);

// The first-order shape functions of a family at `xi`: one value per vertex into `values`
// (which holds at least 8). Pyramids use the rational functions that are bilinear on the base.
void linearShapeFunctions(ElementFamily family, const std::array<double, 3>& xi, double* values);

// The point at `xi` of the straight (first-order) element whose vertices are `corners`: where
// a node of reference coordinates xi sits before it is curved.
Vec3 linearImage(ElementFamily family, const std::array<double, 3>& xi,
                 std::span<const Vec3> corners);

}  // namespace geomesh
