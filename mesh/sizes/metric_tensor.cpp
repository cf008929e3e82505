// Metric tensors: Jacobi eigen-decomposition, anisotropy bounds and metric intersection.
#include "mesh/sizes/metric_tensor.h"

#include <algorithm>
#include <cmath>

namespace geomesh {
namespace {

constexpr double kUnbounded = 1e22;

using Matrix = std::array<std::array<double, 3>, 3>;

Matrix full(const SymmetricTensor& m) {
  return {{{m[0], m[1], m[2]}, {m[1], m[3], m[4]}, {m[2], m[4], m[5]}}};
}

SymmetricTensor packed(const Matrix& a) {
  return {a[0][0], (a[0][1] + a[1][0]) / 2, (a[0][2] + a[2][0]) / 2,
          a[1][1], (a[1][2] + a[2][1]) / 2, a[2][2]};
}

Matrix product(const Matrix& a, const Matrix& b) {
  Matrix c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
  return c;
}

double component(Vec3 v, int k) {
  return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

// One Jacobi rotation zeroing a[p][q]; the rotation is accumulated in v's columns.
void rotate(Matrix& a, Matrix& v, int p, int q) {
  const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
  const double t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
  const double c = 1 / std::sqrt(t * t + 1), s = t * c;
  for (int k = 0; k < 3; ++k) {
    const double akp = a[k][p], akq = a[k][q];
    a[k][p] = c * akp - s * akq;
    a[k][q] = s * akp + c * akq;
  }
  for (int k = 0; k < 3; ++k) {
    const double apk = a[p][k], aqk = a[q][k];
    a[p][k] = c * apk - s * aqk;
    a[q][k] = s * apk + c * aqk;
  }
  for (int k = 0; k < 3; ++k) {
    const double vkp = v[k][p], vkq = v[k][q];
    v[k][p] = c * vkp - s * vkq;
    v[k][q] = s * vkp + c * vkq;
  }
}

}  // namespace

TensorEigen symmetricEigen(const SymmetricTensor& m) {
  Matrix a = full(m);
  Matrix v{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diagonal = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (!(off > 1e-32 * diagonal) || !std::isfinite(off)) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q)
        if (a[p][q] != 0) rotate(a, v, p, q);
  }
  TensorEigen e;
  for (int k = 0; k < 3; ++k) {
    e.values[std::size_t(k)] = a[k][k];
    e.vectors[std::size_t(k)] = {v[0][k], v[1][k], v[2][k]};
  }
  return e;
}

SymmetricTensor tensorFromEigen(const std::array<double, 3>& values,
                                const std::array<Vec3, 3>& vectors) {
  Matrix a{};
  for (std::size_t k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        a[i][j] += values[k] * component(vectors[k], i) * component(vectors[k], j);
  return packed(a);
}

SymmetricTensor symmetrised(const std::array<double, 9>& c) {
  return {c[0], (c[1] + c[3]) / 2, (c[2] + c[6]) / 2, c[4], (c[5] + c[7]) / 2, c[8]};
}

SymmetricTensor isotropicTensor(double size) {
  const double m = 1 / (size * size);
  return {m, 0, 0, m, 0, m};
}

double smallestSize(const SymmetricTensor& m) {
  const TensorEigen e = symmetricEigen(m);
  const double largest = std::max({e.values[0], e.values[1], e.values[2]});
  return largest > 0 && std::isfinite(largest) ? 1 / std::sqrt(largest) : kUnbounded;
}

SymmetricTensor boundedAnisotropy(const SymmetricTensor& m, double anisoMax) {
  TensorEigen e = symmetricEigen(m);
  const double largest = std::max({e.values[0], e.values[1], e.values[2]});
  if (!(largest > 0) || !std::isfinite(largest)) return isotropicTensor(kUnbounded);
  const double ratio = anisoMax > 1 ? anisoMax : 1;
  const double floor = largest / (ratio * ratio);
  for (double& value : e.values) value = std::max(value, floor);
  return tensorFromEigen(e.values, e.vectors);
}

// With a = P D P', a^(1/2) = P D^(1/2) P'; in the frame of a^(-1/2), b becomes
// C = a^(-1/2) b a^(-1/2) = Q L Q', and the intersection is a^(1/2) Q max(1, L) Q' a^(1/2).
SymmetricTensor intersectMetrics(const SymmetricTensor& a, const SymmetricTensor& b) {
  const TensorEigen ea = symmetricEigen(a);
  std::array<double, 3> root{}, inverseRoot{};
  for (std::size_t k = 0; k < 3; ++k) {
    if (!(ea.values[k] > 0)) return b;
    root[k] = std::sqrt(ea.values[k]);
    inverseRoot[k] = 1 / root[k];
  }
  const Matrix half = full(tensorFromEigen(root, ea.vectors));
  const Matrix inverseHalf = full(tensorFromEigen(inverseRoot, ea.vectors));
  const Matrix c = product(product(inverseHalf, full(b)), inverseHalf);
  TensorEigen ec = symmetricEigen(packed(c));
  for (double& value : ec.values) value = std::max(value, 1.0);
  return packed(product(product(half, full(tensorFromEigen(ec.values, ec.vectors))), half));
}

}  // namespace geomesh
