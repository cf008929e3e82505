// integerHomology: column reduction for the kernel, then a diagonal form of the image.
#include "mesh/homology/integer_homology.h"

#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace geomesh {

namespace {

using Vector = std::vector<std::int64_t>;

std::int64_t minusProduct(std::int64_t a, std::int64_t q, std::int64_t b) {
  std::int64_t product = 0, result = 0;
  if (__builtin_mul_overflow(q, b, &product) || __builtin_sub_overflow(a, product, &result))
    throw std::overflow_error("integer overflow in the homology computation");
  return result;
}

// x -= q * y, entry by entry.
void subtractMultiple(Vector& x, std::int64_t q, const Vector& y) {
  for (std::size_t i = 0; i < x.size(); ++i)
    if (y[i] != 0) x[i] = minusProduct(x[i], q, y[i]);
}

// Unimodular column operations on `into` (held as columns), tracked in V (columns) and its
// inverse (rows). Returns the rank r: the columns r.. of V span the kernel.
std::size_t reduceColumns(std::vector<Vector>& columns, std::vector<Vector>& v,
                          std::vector<Vector>& vInverse, std::size_t rows) {
  const std::size_t n = columns.size();
  std::size_t pivot = 0;
  for (std::size_t i = 0; i < rows && pivot < n; ++i) {
    for (;;) {
      std::size_t best = n;
      for (std::size_t j = pivot; j < n; ++j)
        if (columns[j][i] != 0 &&
            (best == n || std::llabs(columns[j][i]) < std::llabs(columns[best][i])))
          best = j;
      if (best == n) break;
      std::swap(columns[best], columns[pivot]);
      std::swap(v[best], v[pivot]);
      std::swap(vInverse[best], vInverse[pivot]);
      bool cleared = true;
      for (std::size_t j = pivot + 1; j < n; ++j) {
        if (columns[j][i] == 0) continue;
        const std::int64_t q = columns[j][i] / columns[pivot][i];
        subtractMultiple(columns[j], q, columns[pivot]);
        subtractMultiple(v[j], q, v[pivot]);
        subtractMultiple(vInverse[pivot], -q, vInverse[j]);
        cleared = cleared && columns[j][i] == 0;
      }
      if (cleared) {
        ++pivot;
        break;
      }
    }
  }
  return pivot;
}

// Brings the smallest nonzero entry of b[t.., t..] to (t, t); false if there is none. Row
// swaps are mirrored on the basis columns.
bool pivotSmallest(std::vector<Vector>& b, std::vector<Vector>& basis, std::size_t t) {
  std::size_t bi = b.size(), bj = 0;
  for (std::size_t i = t; i < b.size(); ++i)
    for (std::size_t j = t; j < b[i].size(); ++j)
      if (b[i][j] != 0 && (bi == b.size() || std::llabs(b[i][j]) < std::llabs(b[bi][bj]))) {
        bi = i;
        bj = j;
      }
  if (bi == b.size()) return false;
  std::swap(b[bi], b[t]);
  std::swap(basis[bi], basis[t]);
  for (Vector& row : b) std::swap(row[bj], row[t]);
  return true;
}

// Clears row t and column t of b but for (t, t); row operations on b change the basis so that
// b keeps giving the image's coordinates in it.
void clearCross(std::vector<Vector>& b, std::vector<Vector>& basis, std::size_t t) {
  for (;;) {
    bool cleared = true;
    for (std::size_t i = t + 1; i < b.size(); ++i) {
      if (b[i][t] == 0) continue;
      const std::int64_t q = b[i][t] / b[t][t];
      subtractMultiple(b[i], q, b[t]);
      subtractMultiple(basis[t], -q, basis[i]);
      cleared = cleared && b[i][t] == 0;
    }
    for (std::size_t j = t + 1; j < b[t].size(); ++j) {
      if (b[t][j] == 0) continue;
      const std::int64_t q = b[t][j] / b[t][t];
      for (Vector& row : b) row[j] = minusProduct(row[j], q, row[t]);
      cleared = cleared && b[t][j] == 0;
    }
    if (cleared) return;
    pivotSmallest(b, basis, t);  // a remainder smaller than the pivot: start again from it
  }
}

}  // namespace

IntegerHomology integerHomology(const IntegerMatrix& into, const IntegerMatrix& from,
                                std::size_t cells) {
  const std::size_t n = cells, rows = into.size();
  std::vector<Vector> columns(n, Vector(rows, 0)), v(n, Vector(n, 0)), vInverse(n, Vector(n, 0));
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < n; ++j) columns[j][i] = into[i][j];
  for (std::size_t j = 0; j < n; ++j) v[j][j] = vInverse[j][j] = 1;
  const std::size_t rank = reduceColumns(columns, v, vInverse, rows);

  // The kernel basis (columns rank.. of V) and the image's coordinates in it.
  const std::size_t above = from.empty() ? 0 : from.front().size();
  std::vector<Vector> basis(v.begin() + rank, v.end());
  std::vector<Vector> b(n - rank, Vector(above, 0));
  for (std::size_t t = 0; t < b.size(); ++t)
    for (std::size_t s = 0; s < n; ++s)
      if (const std::int64_t x = vInverse[rank + t][s]; x != 0)
        for (std::size_t c = 0; c < above; ++c) b[t][c] = minusProduct(b[t][c], -x, from[s][c]);

  IntegerHomology h;
  std::size_t t = 0;
  while (t < b.size() && t < above && pivotSmallest(b, basis, t)) {
    clearCross(b, basis, t);
    if (std::llabs(b[t][t]) > 1) h.torsion.push_back(std::llabs(b[t][t]));
    ++t;
  }
  h.freeBasis.assign(basis.begin() + t, basis.end());
  return h;
}

}  // namespace geomesh
