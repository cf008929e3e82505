// smoothVertices: Laplacian moves accepted when the worst mean ratio around the vertex rises.
#include "mesh/volumes/tet_smoothing.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh/core/predicates.h"
#include "mesh/core/quality.h"

namespace geomesh {

namespace {
constexpr double kUnknown = -2;  // below any measure (those are in [-1, 1])
constexpr std::size_t kLookAhead = 32;  // entries of `around`: about the next ball
}  // namespace

std::size_t smoothVertices(DelaunayTets& mesh, std::uint32_t firstMovable, int passes) {
  const std::size_t count = mesh.points.size();
  if (firstMovable >= count) return 0;
  // Tetrahedra around each vertex, compressed rows.
  std::vector<std::uint32_t> start(count + 1, 0), around;
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t)
    if (mesh.alive(t))
      for (int k = 0; k < 4; ++k) ++start[mesh.vertices[4 * std::size_t{t} + k] + 1];
  for (std::size_t i = 0; i < count; ++i) start[i + 1] += start[i];
  around.resize(start[count]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t)
    if (mesh.alive(t))
      for (int k = 0; k < 4; ++k) around[fill[mesh.vertices[4 * std::size_t{t} + k]]++] = t;

  // Each tetrahedron's measure, computed when first needed and again only after one of its
  // vertices moved: the balls of neighbouring vertices share most of their tetrahedra.
  std::vector<double> measure(mesh.slotCount(), kUnknown);
  auto measureOf = [&](std::uint32_t t) {
    double& m = measure[t];
    if (m == kUnknown) {
      const std::uint32_t* w = &mesh.vertices[4 * std::size_t{t}];
      m = tetMeanRatioCubed(mesh.points[w[0]], mesh.points[w[1]], mesh.points[w[2]],
                            mesh.points[w[3]]);
    }
    return m;
  };
  std::size_t moves = 0;
  for (int pass = 0; pass < passes; ++pass) {
    for (std::uint32_t v = firstMovable; v < count; ++v) {
      const std::uint32_t first = start[v], last = start[v + 1];
      if (first == last) continue;
      // The mean of the other vertices of its tetrahedra (each counted once per tetrahedron:
      // a weighting by how many tetrahedra share a neighbour, which favours the nearer ones).
      Vec3 sum{0, 0, 0};
      double worst = 1;
      for (std::uint32_t i = first; i < last; ++i) {
        // The tetrahedra of the next balls are scattered over the arrays: their loads are
        // started early, so that they overlap this ball's work.
        if (i + kLookAhead < around.size()) {
          const std::uint32_t next = around[i + kLookAhead];
          __builtin_prefetch(&mesh.vertices[4 * std::size_t{next}]);
          __builtin_prefetch(&measure[next]);
        }
        const std::uint32_t* t = &mesh.vertices[4 * std::size_t{around[i]}];
        for (int k = 0; k < 4; ++k)
          if (t[k] != v) sum = sum + mesh.points[t[k]];
        worst = std::min(worst, measureOf(around[i]));
      }
      // A ball whose worst tetrahedron has a mean ratio of 0.8 or more is left: measured on
      // cubes and graded parts, moving those changes nothing.
      if (worst >= 0.8 * 0.8 * 0.8) continue;
      const Vec3 old = mesh.points[v];
      const Vec3 target = sum / (3.0 * (last - first));
      mesh.points[v] = target;
      double better = 1;
      for (std::uint32_t i = first; i < last && better > worst; ++i) {
        const std::uint32_t* t = &mesh.vertices[4 * std::size_t{around[i]}];
        better = std::min(better, tetMeanRatioCubed(mesh.points[t[0]], mesh.points[t[1]],
                                                    mesh.points[t[2]], mesh.points[t[3]]));
      }
      // Positive for certain when the worst is clearly so; else the exact test decides.
      bool accept = better > worst;
      for (std::uint32_t i = first; i < last && accept && better <= kSureMeanRatioCubed; ++i) {
        const std::uint32_t* t = &mesh.vertices[4 * std::size_t{around[i]}];
        accept = orient3d(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]],
                          mesh.points[t[3]]) > 0;
      }
      if (accept) {
        ++moves;
        for (std::uint32_t i = first; i < last; ++i) measure[around[i]] = kUnknown;
      } else {
        mesh.points[v] = old;
      }
    }
  }
  return moves;
}

}  // namespace geomesh
