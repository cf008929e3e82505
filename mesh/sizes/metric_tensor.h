// Metric tensors: eigen-decomposition, anisotropy bounds and intersection of 3x3 metrics.
#pragma once

#include <array>

#include "kernel/vec3.h"

namespace geomesh {

// A symmetric 3x3 matrix as (xx, xy, xz, yy, yz, zz), the layout SizeFields::metric uses. As
// a metric M, it asks for the size 1/sqrt(e'Me) along a unit direction e.
using SymmetricTensor = std::array<double, 6>;

// Eigenvalues and orthonormal eigenvectors (vectors[k] belongs to values[k]).
struct TensorEigen {
  std::array<double, 3> values{};
  std::array<Vec3, 3> vectors{};
};
TensorEigen symmetricEigen(const SymmetricTensor& m);
// sum_k values[k] vectors[k] vectors[k]'.
SymmetricTensor tensorFromEigen(const std::array<double, 3>& values,
                                const std::array<Vec3, 3>& vectors);

// The 9 components of a tensor (row by row), symmetrised.
SymmetricTensor symmetrised(const std::array<double, 9>& components);
// I / h^2.
SymmetricTensor isotropicTensor(double size);
// The smallest size a metric asks for (1/sqrt of its largest eigenvalue); 1e22 when no
// eigenvalue is positive.
double smallestSize(const SymmetricTensor& m);
// The metric with its eigenvalues raised to at least largest / anisoMax^2, so that no aspect
// ratio sqrt(largest / smallest) exceeds anisoMax; a metric with no positive eigenvalue
// becomes the isotropic metric of size 1e22.
SymmetricTensor boundedAnisotropy(const SymmetricTensor& m, double anisoMax);
// The intersection of two positive definite metrics: the largest metric ellipsoid inside both
// unit balls (by simultaneous reduction), so that along every direction the size is at most
// the smaller of the two; equal to either when the other is larger everywhere.
SymmetricTensor intersectMetrics(const SymmetricTensor& a, const SymmetricTensor& b);

}  // namespace geomesh
