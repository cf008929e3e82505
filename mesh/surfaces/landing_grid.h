// LandingGrid: what a node embedded in a surface lands on among the segments and points so far.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "mesh/core/mesh.h"

namespace geomesh {

// The segments (of curves) and isolated points of a surface's input, found by place through a
// uniform grid of cells: an embedded point or curve end that lands on them, closer than
// `tolerance`, would make the triangulation fail, or is already there.
class LandingGrid {
 public:
  // `cell`: the grid's cell size, about the segments' length.
  LandingGrid(const Mesh& mesh, double tolerance, double cell);

  void addSegment(NodeIndex a, NodeIndex b, int curve);
  void addPoint(NodeIndex n);

  struct Landing {
    std::optional<NodeIndex> node;  // another node at the place
    int curve = 0;                  // the curve of a segment through the place (0: none)
  };
  // What the place of node n meets, ignoring the segments and points that are n itself.
  Landing find(NodeIndex n) const;

 private:
  using Cell = std::array<std::int64_t, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const;
  };
  struct Segment {
    NodeIndex a, b;
    int curve;  // 0 for an isolated point (a == b)
  };
  Cell cellOf(Vec3 p) const;
  void insert(std::uint32_t segment, Vec3 lo, Vec3 hi);

  const Mesh& mesh_;
  double tolerance_, cell_;
  std::vector<Segment> segments_;
  std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> cells_;
};

}  // namespace geomesh
