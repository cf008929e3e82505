// -check on surfaces: the topology of each connected part of a surface triangulation, one line
// each, as the check report prints them.
#pragma once

#include <string>
#include <vector>

#include "mesh/discrete/triangulation.h"

namespace geomesh {

// "Check: surface part 1 of 2: 320 triangles, Euler characteristic 2, genus 0, 0 boundary
// loops, 0 non-manifold edges, 0 inconsistently oriented edges" for each part of `t`
// connected through shared vertices; one line saying so when `t` has no triangle; then, if
// triangles that share no vertex cross each other, a line with their count and a point.
std::vector<std::string> surfaceTopologyLines(const Triangulation& t);

}  // namespace geomesh
