// expandRange, linSpace and logSpace, stepping by repeated addition as Gmsh does.
#include "stdlib/ranges.h"

#include <cmath>
#include <stdexcept>

namespace geomesh {

// Like Gmsh, the value grows by repeated addition and the range stops as soon as it passes
// `last`, with no tolerance: 0:1:0.1 has 11 values, the last one 0.9999999999999999, and
// 0:0.3:0.1 has 3.
std::vector<double> expandRange(double first, double last, std::optional<double> step) {
  const double delta = step ? *step : (first <= last ? 1.0 : -1.0);
  if (delta == 0) throw std::invalid_argument("range step must not be zero");
  std::vector<double> values;
  if ((last - first) / delta > 10'000'000) throw std::invalid_argument("range has too many values");
  for (double x = first; delta > 0 ? x <= last : x >= last; x += delta) values.push_back(x);
  return values;
}

std::vector<double> linSpace(double a, double b, int n) {
  std::vector<double> values;
  if (n <= 0) return values;
  if (n == 1) return {a};
  for (int i = 0; i < n; ++i) values.push_back(a + (b - a) * i / (n - 1));
  return values;
}

std::vector<double> logSpace(double a, double b, int n) {
  std::vector<double> values = linSpace(a, b, n);
  for (double& v : values) v = std::pow(10.0, v);
  return values;
}

}  // namespace geomesh
