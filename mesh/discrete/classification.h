// Classification of a merged triangulation (STL, scan) into patches, curves and points, as the
// ClassifySurfaces and CreateTopology statements do, and the repairs such input needs first
// (welding duplicate vertices, consistent orientation).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "mesh/discrete/triangulation.h"

namespace geomesh {

struct ClassifyOptions {
  // Radians: an edge whose two triangles' normals differ by more than this separates patches.
  double angle = 40 * std::numbers::pi / 180;
  // Edges between triangles of different input surfaces (different labels) also separate patches.
  bool includeBoundary = true;
  // Split patches until each is a topological disk (genus 0, exactly one boundary loop).
  bool forReparametrization = false;
  // Radians: a curve is split at a vertex where its consecutive edges turn by more than this
  // (pi: never).
  double curveAngle = std::numbers::pi;
};

// Patches, curves and points of a triangulation.
struct DiscreteTopology {
  // Vertices of the triangulation that become model points, ascending, unique.
  std::vector<std::uint32_t> points;
  struct Curve {
    // Consecutive triangulation vertices along the curve; it starts and ends at entries of
    // `points`. A closed curve has front() == back().
    std::vector<std::uint32_t> vertices;
  };
  std::vector<Curve> curves;
  struct Patch {
    std::vector<std::uint32_t> triangles;  // ascending indices into Triangulation::triangles
    // Boundary loops as signed 1-based curve indices (+c: curves[c-1] followed from
    // vertices.front() to back(), -c: backwards), each loop closed and chained, run so that the
    // patch's triangles lie on its left. The longest loop (by 3D length) first.
    std::vector<std::vector<int>> loops;
  };
  std::vector<Patch> patches;
};

// New labels (0-based, consecutive, numbered by smallest triangle) per triangle: connected
// regions of triangles joined across manifold edges whose dihedral angle is at most
// options.angle and (when includeBoundary) whose two triangles had the same input label; then,
// if forReparametrization, regions split until each is a topological disk. `labels` holds one
// entry per triangle, or is empty (one input surface).
std::vector<int> classifyByAngle(const Triangulation& t, std::span<const int> labels,
                                 const ClassifyOptions& options);

// The topology the labels give: patches are connected components of equally labelled triangles
// (across manifold edges); curves are maximal chains of feature edges (between two patches,
// free, or non-manifold) broken where three or more feature edges meet, where the patches along
// the chain change, and where the chain turns by more than curveAngle. A closed chain without a
// break gets one point, its smallest vertex. `labels` as for classifyByAngle.
DiscreteTopology buildTopology(const Triangulation& t, std::span<const int> labels,
                               double curveAngle);

// Splits a connected set of triangles into two connected halves of similar size, grown
// breadth-first from two far-apart seeds (the farthest from triangles[0], then the farthest
// from that). Both halves ascending; the second is empty for a single triangle.
std::array<std::vector<std::uint32_t>, 2> splitPatch(const Triangulation& t,
                                                     std::span<const std::uint32_t> triangles);

// Euler characteristic V - E + F and number of boundary loops of a set of triangles.
struct PatchShape {
  int euler = 0;
  int boundaryLoops = 0;
  int genus() const { return (2 - euler - boundaryLoops) / 2; }
  bool isDisk() const { return euler == 1 && boundaryLoops == 1; }
};
PatchShape patchShape(const Triangulation& t, std::span<const std::uint32_t> triangles);

// Merges vertices at most `tolerance` apart (each onto the first of them, so no chains form),
// drops the points no longer used by a merge and the triangles that became degenerate or
// duplicated (same three vertices, in any order). Returns the number of vertices merged.
// `labels`, when given, holds a value per triangle and is kept in step with the triangles.
std::size_t mergeDuplicateVertices(Triangulation& t, double tolerance,
                                   std::vector<int>* labels = nullptr);

// Orients each connected component (across manifold edges) like its smallest triangle,
// breadth-first. Returns the number of triangles flipped.
std::size_t orientConsistently(Triangulation& t);

}  // namespace geomesh
