// Helpers shared by the files of the built-in kernel (not part of its interface).
#pragma once

#include <algorithm>
#include <sstream>
#include <vector>

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

// The same chain of signed curves (or surfaces) run the other way.
inline std::vector<int> reversedChain(std::vector<int> chain) {
  std::reverse(chain.begin(), chain.end());
  for (int& c : chain) c = -c;
  return chain;
}

}  // namespace geomesh::geo_detail
