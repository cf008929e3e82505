// Reals written as text in the fewest digits that read back to the same double.
#pragma once

#include <charconv>
#include <ostream>

namespace geomesh {

inline void writeShortestReal(std::ostream& out, double v) {
  char digits[32];
  out.write(digits, std::to_chars(digits, digits + sizeof digits, v).ptr - digits);
}

}  // namespace geomesh
