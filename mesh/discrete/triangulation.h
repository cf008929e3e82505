// Triangulation: a triangulated surface as flat arrays (points, triangles, neighbours across
// edges), the data every algorithm on merged triangulations (STL, scans) works on.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "kernel/vec3.h"

namespace geomesh {

using TriangleVertices = std::array<std::uint32_t, 3>;

// Points and triangles; a triangle's vertices run counter-clockwise seen from the side its
// normal points to.
struct Triangulation {
  std::vector<Vec3> points;
  std::vector<TriangleVertices> triangles;
};

inline constexpr std::uint32_t kNoTriangle = 0xffffffffu;

// neighbours[t][k]: the triangle that shares edge k of t (from vertex k to vertex k + 1 mod 3),
// kNoTriangle on a boundary edge (one triangle) and on a non-manifold edge (three or more).
struct TriangleAdjacency {
  std::vector<std::array<std::uint32_t, 3>> neighbours;
  // The vertex pairs of the edges shared by three triangles or more, each once, sorted.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> nonManifoldEdges;
};

TriangleAdjacency triangleAdjacency(std::span<const TriangleVertices> triangles);

// The boundary of a set of triangles as closed vertex cycles (the first vertex not repeated),
// each run in the direction its triangles give it, so that they lie on its left. Edges used by
// one triangle only; a vertex where the boundary touches itself starts a new cycle there.
std::vector<std::vector<std::uint32_t>> boundaryLoops(std::span<const TriangleVertices> triangles);

// Union-find over indices (vertices, triangles), its representative the smallest index of
// its set.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t count);
  std::uint32_t find(std::uint32_t a);
  void join(std::uint32_t a, std::uint32_t b);

 private:
  std::vector<std::uint32_t> parent_;
};

Vec3 triangleNormal(const Triangulation& t, std::uint32_t triangle);  // unit (zero if degenerate)
double triangleArea(const Triangulation& t, std::uint32_t triangle);

}  // namespace geomesh
