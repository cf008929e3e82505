// Bases of the homology or cohomology spaces of a (relative) cell complex over the integers.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/homology/cell_complex.h"
#include "mesh/homology/chain_reduction.h"

namespace geomesh {

enum class HomologyKind { Homology, Cohomology };

// Per dimension k: the rank of the free part of H_k (or H^k), a chain (or cochain) of k-cells
// for each basis element of it, and the torsion coefficients. Each homology chain is a cycle
// (its boundary in the complex is zero) and each cohomology cochain a cocycle (it vanishes on
// every boundary), none of them homologous to zero. The sizes of the complex before and after
// its reduction are kept for the log.
struct HomologyBases {
  HomologyKind kind = HomologyKind::Homology;
  std::array<int, 4> ranks{};
  std::array<std::vector<Chain>, 4> generators;
  std::array<std::vector<std::int64_t>, 4> torsion;
  std::array<std::size_t, 4> reducedCells{};  // cells left per dimension after the reduction
};

HomologyBases computeHomologyBases(const CellComplex& complex, HomologyKind kind);

}  // namespace geomesh
