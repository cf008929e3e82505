// Shrinking a cell complex to a few cells with the same homology, by coreductions and
// collapses, and mapping what is left back to chains of the whole complex.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/homology/cell_complex.h"

namespace geomesh {

// Which way the complex is read. Primal: a cell's boundary is its faces, and the reduction
// serves homology. Dual: a cell's "boundary" is its cofaces (the coboundary, transposed), the
// levels run from the volumes (level 0) to the vertices (level 3), and the reduction serves
// cohomology. Level of a cell: its dimension, or 3 minus it.
enum class ComplexSide { Primal, Dual };

// A chain (or cochain): cells with nonzero integer coefficients, ascending cells.
using Chain = std::vector<std::pair<CellId, std::int64_t>>;

// An elimination: `lower` (one level below `upper`) leaves with `upper`; `coefficient` is the
// incidence of `lower` in the boundary of `upper` (+1 or -1).
struct ReductionPair {
  CellId lower, upper;
  std::int32_t coefficient;
};

// The result of reduceComplex: the eliminations in order, and the cells left (the critical
// cells, ascending) whose small complex has the homology of the whole.
struct ComplexReduction {
  ComplexSide side = ComplexSide::Primal;
  std::vector<ReductionPair> pairs;
  std::vector<CellId> critical;
};

// Eliminates pairs of cells, first by coreductions (a cell whose boundary has one cell left
// goes with it, spreading from the cells whose boundary is empty, breadth first), then by
// collapses (a cell that bounds only one cell goes with it). Each cell is handled a bounded
// number of times: the cost is linear in the size of the complex.
ComplexReduction reduceComplex(const CellComplex& complex, ComplexSide side);

// The small complex of the critical cells: per critical cell, the chain of the whole complex
// it stands for (a chain map: the boundary of the chain is the chain of its small boundary),
// and the boundary matrices between levels.
struct MorseComplex {
  std::array<std::vector<CellId>, 4> cells;  // critical cells per level
  std::array<std::vector<Chain>, 4> chains;  // the chain each stands for
  // boundary[k][i][j]: coefficient of cells[k-1][i] in the boundary of cells[k][j] (k >= 1).
  std::array<std::vector<std::vector<std::int64_t>>, 4> boundary;
};

MorseComplex morseComplex(const CellComplex& complex, const ComplexReduction& reduction);

// Level of a cell on a side.
inline int levelOf(const CellComplex& complex, CellId c, ComplexSide side) {
  const int dim = complex.dimension(c);
  return side == ComplexSide::Primal ? dim : 3 - dim;
}

}  // namespace geomesh
