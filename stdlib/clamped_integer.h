// clampedInteger: a script's number truncated and clamped into an integer type, NaN as 0.
#pragma once

#include <cmath>
#include <limits>

namespace geomesh {

// x rounded toward zero and clamped into the range of T (NaN gives 0): converting whatever
// number a script computed never overflows.
template <class T>
T clampedInteger(double x) {
  constexpr T lowest = std::numeric_limits<T>::lowest(), highest = std::numeric_limits<T>::max();
  if (std::isnan(x)) return 0;
  if (x <= static_cast<double>(lowest)) return lowest;
  if (x >= static_cast<double>(highest)) return highest;
  return static_cast<T>(x);
}

}  // namespace geomesh
