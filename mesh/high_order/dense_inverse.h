// invertDense: the inverse of a small dense square matrix, for the bases of high-order elements.
#pragma once

#include <cstddef>
#include <vector>

namespace geomesh {

// Replaces the row-major n x n matrix `a` by its inverse (Gauss-Jordan with partial
// pivoting). Returns false, leaving `a` unspecified, when a pivot is below `relativeTolerance`
// times the largest entry: the matrix is singular for the purposes of a basis.
bool invertDense(std::vector<double>& a, std::size_t n, double relativeTolerance = 1e-12);

}  // namespace geomesh
