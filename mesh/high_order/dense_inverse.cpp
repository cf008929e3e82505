// Gauss-Jordan elimination in place, on matrices of at most a few hundred rows.
#include "mesh/high_order/dense_inverse.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace geomesh {

bool invertDense(std::vector<double>& a, std::size_t n, double relativeTolerance) {
  double scale = 0;
  for (double v : a) scale = std::max(scale, std::abs(v));
  if (scale == 0) return n == 0;
  std::vector<std::size_t> columnOf(n);  // row swaps, undone on the columns at the end
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pivot = k;
    for (std::size_t r = k + 1; r < n; ++r)
      if (std::abs(a[r * n + k]) > std::abs(a[pivot * n + k])) pivot = r;
    if (std::abs(a[pivot * n + k]) <= relativeTolerance * scale) return false;
    columnOf[k] = pivot;
    if (pivot != k)
      for (std::size_t c = 0; c < n; ++c) std::swap(a[k * n + c], a[pivot * n + c]);
    const double inv = 1 / a[k * n + k];
    a[k * n + k] = 1;
    for (std::size_t c = 0; c < n; ++c) a[k * n + c] *= inv;
    for (std::size_t r = 0; r < n; ++r) {
      if (r == k) continue;
      const double f = a[r * n + k];
      if (f == 0) continue;
      a[r * n + k] = 0;
      for (std::size_t c = 0; c < n; ++c) a[r * n + c] -= f * a[k * n + c];
    }
  }
  for (std::size_t k = n; k-- > 0;)
    if (columnOf[k] != k)
      for (std::size_t r = 0; r < n; ++r) std::swap(a[r * n + k], a[r * n + columnOf[k]]);
  return true;
}

}  // namespace geomesh
