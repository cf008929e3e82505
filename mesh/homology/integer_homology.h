// Homology of a small chain complex over the integers, from its boundary matrices.
#pragma once

#include <cstdint>
#include <vector>

namespace geomesh {

// A dense integer matrix as rows.
using IntegerMatrix = std::vector<std::vector<std::int64_t>>;

// The homology at one level of a chain complex: a basis of the free part (vectors over the
// cells of the level) and the torsion coefficients (each above 1).
struct IntegerHomology {
  std::vector<std::vector<std::int64_t>> freeBasis;
  std::vector<std::int64_t> torsion;
};

// H = ker(into) / im(from), where `into` maps the level's n cells to the level below (rows: the
// cells below; n columns) and `from` maps the level above into it (n rows). Empty matrices
// stand for zero maps; `cells` is n. Requires into * from = 0. Unimodular column reduction of
// `into` gives a basis of its kernel; diagonalizing the image's coordinates in that basis with
// unimodular operations splits the quotient. Throws std::overflow_error if a coefficient
// leaves 64 bits.
IntegerHomology integerHomology(const IntegerMatrix& into, const IntegerMatrix& from,
                                std::size_t cells);

}  // namespace geomesh
