// Finite differences of a scalar field: gradient, curvature, Laplacian, Hessian, mean.
#pragma once

#include <array>

#include "kernel/vec3.h"

namespace geomesh {

// The stencils the reference's derived size fields use, on any callable g(Vec3) -> double, with
// step h. First derivatives are central differences over [p - h/2, p + h/2]; second ones over
// [p - h, p + h] (mixed ones over the corners of a square of side h).

inline Vec3 axisStep(int axis, double h) {
  return axis == 0 ? Vec3{h, 0, 0} : axis == 1 ? Vec3{0, h, 0} : Vec3{0, 0, h};
}

template <class G>
Vec3 differenceGradient(const G& g, Vec3 p, double h) {
  const Vec3 dx = axisStep(0, h / 2), dy = axisStep(1, h / 2), dz = axisStep(2, h / 2);
  return {(g(p + dx) - g(p - dx)) / h, (g(p + dy) - g(p - dy)) / h, (g(p + dz) - g(p - dz)) / h};
}

// div(grad g / |grad g|): the unit gradient at p +- h/2 along each axis, differenced. Where the
// gradient vanishes, it is taken as is (zero).
template <class G>
double differenceCurvature(const G& g, Vec3 p, double h) {
  double sum = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 s = axisStep(axis, h / 2);
    const Vec3 plus = normalized(differenceGradient(g, p + s, h));
    const Vec3 minus = normalized(differenceGradient(g, p - s, h));
    const Vec3 change = plus - minus;
    sum += axis == 0 ? change.x : axis == 1 ? change.y : change.z;
  }
  return sum / h;
}

// The sum of the six neighbours at distance h, less six times the centre, over h^2.
template <class G>
double differenceLaplacian(const G& g, Vec3 p, double h) {
  double sum = -6 * g(p);
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 s = axisStep(axis, h);
    sum += g(p + s) + g(p - s);
  }
  return sum / (h * h);
}

// The mean of g at p and its six neighbours at distance h.
template <class G>
double differenceMean(const G& g, Vec3 p, double h) {
  double sum = g(p);
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 s = axisStep(axis, h);
    sum += g(p + s) + g(p - s);
  }
  return sum / 7;
}

// The Hessian as (xx, yy, zz, xy, xz, yz).
template <class G>
std::array<double, 6> differenceHessian(const G& g, Vec3 p, double h) {
  std::array<double, 6> m{};
  const double centre = g(p);
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 s = axisStep(axis, h);
    m[axis] = (g(p + s) - 2 * centre + g(p - s)) / (h * h);
  }
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = axisStep(pairs[k][0], h / 2), b = axisStep(pairs[k][1], h / 2);
    m[3 + k] = (g(p + a + b) - g(p + a - b) - g(p - a + b) + g(p - a - b)) / (h * h);
  }
  return m;
}

// The largest eigenvalue of the symmetric matrix (xx, yy, zz, xy, xz, yz).
double largestEigenvalue(const std::array<double, 6>& m);

}  // namespace geomesh
