// DiscreteModel: the merged triangulations a session classifies and gives geometry to.
#pragma once

#include <cstdint>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "mesh/discrete/triangulation.h"

namespace geomesh {

// The triangles of a session's discrete surfaces (merged STL, PLY, OFF... files), welded and
// consistently oriented, with the entities the built-in factory holds of them: which surface
// each triangle belongs to, the vertices each discrete curve runs through and the vertex of
// each discrete point. The factory's entities and this stay in step: ClassifySurfaces,
// CreateTopology and CreateGeometry change both.
struct DiscreteModel {
  Triangulation triangulation;
  std::vector<int> surfaceOf;                        // per triangle: its surface's tag
  std::map<int, std::vector<std::vector<int>>> loops;  // surface -> its loops (signed curves)
  std::map<int, std::vector<std::uint32_t>> curves;   // curve -> its vertices, in order
  std::map<int, std::uint32_t> points;                // point -> its vertex
  std::string file;                                   // the file merged first
  double curveAngle = std::numbers::pi;               // curves break where they turn more
};

}  // namespace geomesh
