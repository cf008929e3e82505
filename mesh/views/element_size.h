// The size of a mesh element as one length: the edge of the regular element of equal measure.
#pragma once

#include <cmath>

#include "mesh/core/element_type.h"

namespace geomesh::post {

// The edge length of the regular element of the same family and the same measure (length,
// area or volume): a segment's length; the equilateral triangle's sqrt(4 A / sqrt 3); the
// regular tetrahedron's cbrt(6 sqrt2 V); the square's and cube's side; the right prism on an
// equilateral triangle with square sides, cbrt(4 V / sqrt 3); the square pyramid with all
// edges equal, cbrt(3 sqrt2 V). 0 for points. Error-driven size fields use the same rule.
inline double equivalentElementSize(ElementFamily family, double measure) {
  const double sqrt2 = std::sqrt(2.0), sqrt3 = std::sqrt(3.0);
  switch (family) {
    case ElementFamily::Point:
      return 0;
    case ElementFamily::Line:
      return measure;
    case ElementFamily::Triangle:
      return std::sqrt(4 * measure / sqrt3);
    case ElementFamily::Quad:
      return std::sqrt(measure);
    case ElementFamily::Tet:
      return std::cbrt(6 * sqrt2 * measure);
    case ElementFamily::Hex:
      return std::cbrt(measure);
    case ElementFamily::Prism:
      return std::cbrt(4 * measure / sqrt3);
    case ElementFamily::Pyramid:
      return std::cbrt(3 * sqrt2 * measure);
  }
  return 0;
}

}  // namespace geomesh::post
