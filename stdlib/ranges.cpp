#include "stdlib/ranges.h"

#include <cmath>
#include <stdexcept>

namespace geomesh {

std::vector<double> expandRange(double first, double last, std::optional<double> step) {
  const double delta = step ? *step : (first <= last ? 1.0 : -1.0);
  if (delta == 0) throw std::invalid_argument("range step must not be zero");
  std::vector<double> values;
  const double span = (last - first) / delta;
  if (span < -1e-10) return values;
  // A relative tolerance absorbs rounding: 0:1:0.1 ends at 1, not 0.9.
  const auto count = static_cast<long long>(std::floor(span + 1e-10 * std::max(1.0, span))) + 1;
  if (count > 10'000'000) throw std::invalid_argument("range has too many values");
  values.reserve(static_cast<std::size_t>(count));
  for (long long i = 0; i < count; ++i) values.push_back(first + static_cast<double>(i) * delta);
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
