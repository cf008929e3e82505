// transfiniteFractions: node fractions for the Progression, Bump and Beta laws.
#include "mesh/curves/transfinite_curve.h"

#include <algorithm>
#include <cmath>

namespace geomesh {
namespace {

double evenly(int k, int segments) { return static_cast<double>(k) / segments; }

double progression(int k, int segments, double r) {
  if (!(r > 0) || std::abs(r - 1) < 1e-12) return evenly(k, segments);
  return (std::pow(r, k) - 1) / (std::pow(r, segments) - 1);
}

// The antiderivative of 1/(1 + a s^2), centred at s = 0.
double inverseSizeIntegral(double s, double a) {
  if (std::abs(a) < 1e-12) return s;
  if (a > 0) return std::atan(std::sqrt(a) * s) / std::sqrt(a);
  return std::atanh(std::sqrt(-a) * s) / std::sqrt(-a);
}

double bump(int k, int segments, double c) {
  if (!(c > 0)) return evenly(k, segments);
  const double a = 4 * (c - 1);  // h(s) = 1 + a s^2 on s in [-1/2, 1/2]
  const double half = inverseSizeIntegral(0.5, a);
  const double target = -half + 2 * half * evenly(k, segments);
  // Invert the antiderivative in closed form.
  double s = target;
  if (a > 1e-12) s = std::tan(std::sqrt(a) * target) / std::sqrt(a);
  if (a < -1e-12) s = std::tanh(std::sqrt(-a) * target) / std::sqrt(-a);
  return std::clamp(s + 0.5, 0.0, 1.0);
}

double beta(int k, int segments, double b) {
  if (!(b > 1)) return evenly(k, segments);
  const double q = (b + 1) / (b - 1);
  const double p = std::pow(q, 1 - evenly(k, segments));
  return ((b + 1) - (b - 1) * p) / (p + 1);
}

}  // namespace

std::vector<double> transfiniteFractions(const TransfiniteCurve& law) {
  const int segments = std::max(law.nodes, 2) - 1;
  std::vector<double> x(static_cast<std::size_t>(segments) + 1);
  for (int k = 0; k <= segments; ++k) {
    switch (law.law) {
      case TransfiniteCurve::Law::Progression:
        x[k] = progression(k, segments, law.coefficient);
        break;
      case TransfiniteCurve::Law::Bump: x[k] = bump(k, segments, law.coefficient); break;
      case TransfiniteCurve::Law::Beta: x[k] = beta(k, segments, law.coefficient); break;
    }
  }
  x.front() = 0;
  x.back() = 1;
  if (law.reversed) {
    std::reverse(x.begin(), x.end());
    for (double& v : x) v = 1 - v;
  }
  return x;
}

}  // namespace geomesh
