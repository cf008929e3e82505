#pragma once

// Error helpers shared by the files of the built-in kernel (not part of its interface).

#include <sstream>

#include "kernel/geometry_error.h"

namespace geomesh::geo_detail {

template <class... Parts>
[[noreturn]] void fail(const Parts&... parts) {
  std::ostringstream out;
  (out << ... << parts);
  throw GeometryError(out.str());
}

template <class Map>
void requireNew(const Map& map, int tag, const char* what) {
  if (map.contains(tag)) fail(what, " ", tag, " already exists");
}

}  // namespace geomesh::geo_detail
