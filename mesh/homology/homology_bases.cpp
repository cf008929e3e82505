// computeHomologyBases: reduce, compute on the small complex, map the bases back.
#include "mesh/homology/homology_bases.h"

#include <algorithm>
#include <map>

#include "mesh/homology/integer_homology.h"

namespace geomesh {

namespace {

// Sum of coeff * chain over a basis vector of the small complex.
Chain combine(const std::vector<Chain>& chains, const std::vector<std::int64_t>& coefficients) {
  std::map<CellId, std::int64_t> sum;
  for (std::size_t i = 0; i < chains.size(); ++i)
    if (coefficients[i] != 0)
      for (const auto& [cell, c] : chains[i]) sum[cell] += coefficients[i] * c;
  Chain out;
  for (const auto& [cell, c] : sum)
    if (c != 0) out.push_back({cell, c});
  return out;
}

}  // namespace

HomologyBases computeHomologyBases(const CellComplex& complex, HomologyKind kind) {
  const ComplexSide side = kind == HomologyKind::Homology ? ComplexSide::Primal : ComplexSide::Dual;
  const ComplexReduction reduction = reduceComplex(complex, side);
  const MorseComplex morse = morseComplex(complex, reduction);
  HomologyBases bases;
  bases.kind = kind;
  for (int level = 0; level <= 3; ++level) {
    const IntegerMatrix none;
    const IntegerMatrix& from = level < 3 ? morse.boundary[level + 1] : none;
    const IntegerHomology h =
        integerHomology(morse.boundary[level], from, morse.cells[level].size());
    const int dim = side == ComplexSide::Primal ? level : 3 - level;
    bases.ranks[dim] = static_cast<int>(h.freeBasis.size());
    bases.torsion[dim] = h.torsion;
    bases.reducedCells[dim] = morse.cells[level].size();
    for (const auto& vector : h.freeBasis)
      bases.generators[dim].push_back(combine(morse.chains[level], vector));
  }
  return bases;
}

}  // namespace geomesh
