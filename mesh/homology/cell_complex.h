// CellComplex: the cells of a set of mesh elements and of all their faces, with signed
// incidences both ways, relative to a subcomplex that is left out.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/core/element_type.h"
#include "mesh/core/mesh.h"

namespace geomesh {

using CellId = std::uint32_t;

// A mesh element as the complex sees it: its shape and its corner nodes in element order.
struct ComplexElement {
  ElementFamily family = ElementFamily::Point;
  std::array<NodeIndex, 8> corners{};
};

// One cell of the boundary (or coboundary) of another, with its incidence number (+1 or -1).
struct Incidence {
  CellId cell;
  std::int32_t sign;
};

// The cells are numbered by dimension: the vertices first, then the edges, the faces and the
// volumes. Each cell has an orientation: a volume has that of its element, a face runs round
// from its smallest node towards the smaller of that node's neighbours, an edge runs from its
// smaller node to its larger one. The boundary of every cell is consistent with these
// orientations, so that the boundary of a boundary is zero.
class CellComplex {
 public:
  std::size_t size() const { return family_.size(); }
  std::size_t count(int dim) const { return first_[dim + 1] - first_[dim]; }
  CellId first(int dim) const { return first_[dim]; }
  int dimension(CellId c) const;
  ElementFamily family(CellId c) const { return family_[c]; }
  // Corner nodes in the order that gives the cell its orientation.
  std::span<const NodeIndex> nodes(CellId c) const {
    return {nodes_.data() + nodeStart_[c], nodes_.data() + nodeStart_[c + 1]};
  }
  std::span<const Incidence> faces(CellId c) const {
    return {faces_.data() + faceStart_[c], faces_.data() + faceStart_[c + 1]};
  }
  std::span<const Incidence> cofaces(CellId c) const {
    return {cofaces_.data() + cofaceStart_[c], cofaces_.data() + cofaceStart_[c + 1]};
  }
  // The highest dimension holding a cell (-1 when empty).
  int topDimension() const;

 private:
  friend class CellComplexBuilder;
  std::array<CellId, 5> first_{};
  std::vector<ElementFamily> family_;
  std::vector<std::uint32_t> nodeStart_{0};
  std::vector<NodeIndex> nodes_;
  std::vector<std::uint32_t> faceStart_{0};
  std::vector<Incidence> faces_;
  std::vector<std::uint32_t> cofaceStart_{0};
  std::vector<Incidence> cofaces_;
};

// The complex of the `domain` elements and all their faces, minus the cells of the
// `subdomain` elements and of all their faces (a relative complex). Elements are matched by
// their corner nodes; repeated elements count once. Cost: sorting the face occurrences.
CellComplex buildCellComplex(std::span<const ComplexElement> domain,
                             std::span<const ComplexElement> subdomain);

}  // namespace geomesh
