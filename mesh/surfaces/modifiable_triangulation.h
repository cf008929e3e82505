#pragma once

#include <cstdint>
#include <vector>

#include "mesh/surfaces/delaunay2d.h"

namespace geomesh {

// The triangles of a domain in corner form, as in Triangulation2D (corner 3t+i: vertex i of
// t and the edge opposite it), with the local modifications of mesh adaptation: edge splits
// and flips, vertex removal by edge collapse. The neighbour across a boundary edge is kNone.
// Removed triangles are reused; callers check validity (orientation, link condition) before
// modifying.
class ModifiableTriangulation {
 public:
  // The triangles of `tri` flagged in `inside`, with all the points of `tri`.
  ModifiableTriangulation(const Triangulation2D& tri, const std::vector<std::uint8_t>& inside);

  static std::uint32_t nextCorner(std::uint32_t c) { return c % 3 == 2 ? c - 2 : c + 1; }
  static std::uint32_t prevCorner(std::uint32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }

  Vec2 point(std::uint32_t v) const { return points_[v]; }
  std::size_t pointCount() const { return points_.size(); }
  std::uint32_t addPoint(Vec2 p) {
    points_.push_back(p);
    triangleOf_.push_back(kNone);
    return static_cast<std::uint32_t>(points_.size() - 1);
  }
  void movePoint(std::uint32_t v, Vec2 p) { points_[v] = p; }
  bool inMesh(std::uint32_t v) const { return triangleOf_[v] != kNone; }

  std::size_t triangleCount() const { return alive_.size(); }
  bool alive(std::uint32_t t) const { return alive_[t] != 0; }
  std::uint32_t vertex(std::uint32_t c) const { return vertex_[c]; }
  std::uint32_t neighbour(std::uint32_t c) const { return neighbour_[c]; }
  EdgeKind kind(std::uint32_t c) const { return kind_[c]; }

  // The corners of v in its triangles, counter-clockwise around v. Returns false when v is
  // on the boundary; the first triangle is then the one after the boundary edge.
  bool ring(std::uint32_t v, std::vector<std::uint32_t>& corners) const;
  // A corner opposite the edge {a, b}, or kNone.
  std::uint32_t findEdge(std::uint32_t a, std::uint32_t b) const;
  // Splits the free edge of `corner` at new vertex m: its two triangles become four.
  void split(std::uint32_t corner, std::uint32_t m);
  // Replaces the two triangles of the free edge of `corner` by those of the other diagonal.
  void flip(std::uint32_t corner);
  // Removes interior vertex v, whose counter-clockwise corners are `ringOfV`, by merging it
  // into its neighbour w; the two triangles of edge (v, w) disappear.
  void collapse(std::uint32_t v, std::uint32_t w, const std::vector<std::uint32_t>& ringOfV);

 private:
  std::uint32_t cornerOf(std::uint32_t t, std::uint32_t v) const {
    return 3 * t + (vertex_[3 * t] == v ? 0 : vertex_[3 * t + 1] == v ? 1 : 2);
  }
  std::uint32_t newTriangle();
  void setTriangle(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c);
  void link(std::uint32_t c1, std::uint32_t c2, EdgeKind k);

  std::vector<Vec2> points_;
  std::vector<std::uint32_t> triangleOf_;  // per vertex: a triangle around it, or kNone
  std::vector<std::uint32_t> vertex_, neighbour_;
  std::vector<EdgeKind> kind_;
  std::vector<std::uint8_t> alive_;
  std::vector<std::uint32_t> free_;
  mutable std::vector<std::uint32_t> scratch_;
};

}  // namespace geomesh
