// expandRange (first:last:step as Gmsh lists it), LinSpace and LogSpace.
#pragma once

#include <optional>
#include <vector>

namespace geomesh {

// The values of the range first:last:step, as Gmsh lists them: {1:3} is 1, 2, 3; {3:1} is
// 3, 2, 1 (the default step follows the direction); {0:1:0.1} has 11 values despite rounding;
// a step going away from `last` gives no value. Throws std::invalid_argument for a zero step.
std::vector<double> expandRange(double first, double last, std::optional<double> step);

// n values evenly spaced from a to b (LinSpace), and their powers of ten (LogSpace).
std::vector<double> linSpace(double a, double b, int n);
std::vector<double> logSpace(double a, double b, int n);

}  // namespace geomesh
