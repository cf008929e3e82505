// Implicit mean-curvature flow: each iteration solves (M + dt L) x' = M x, with L the cotangent
// stiffness matrix and M the lumped area, over the free vertices; the fixed ones move to the
// right-hand side. Implicit steps stay stable for time steps far beyond the explicit limit.
#include "mesh/discrete/surface_fairing.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "mesh/discrete/surface_curvature.h"
#include "mesh/discrete/surface_topology.h"

namespace geomesh {
namespace {

constexpr std::int64_t kFixed = -1;

double meanEdgeLength(const Triangulation& t) {
  double sum = 0;
  for (const TriangleVertices& v : t.triangles)
    for (int k = 0; k < 3; ++k) sum += distance(t.points[v[k]], t.points[v[(k + 1) % 3]]);
  return t.triangles.empty() ? 0 : sum / (3.0 * t.triangles.size());
}

bool isClosed(const Triangulation& t) {
  const TriangleAdjacency adjacency = triangleAdjacency(t.triangles);
  return std::all_of(adjacency.neighbours.begin(), adjacency.neighbours.end(), [](const auto& n) {
    return n[0] != kNoTriangle && n[1] != kNoTriangle && n[2] != kNoTriangle;
  });
}

double enclosedVolume(const Triangulation& t) {
  double sixTimes = 0;
  for (const TriangleVertices& v : t.triangles)
    sixTimes += dot(t.points[v[0]], cross(t.points[v[1]], t.points[v[2]]));
  return sixTimes / 6;
}

// The unknown's number of each vertex: kFixed for the fixed vertices and those of no triangle.
std::vector<std::int64_t> numberUnknowns(const Triangulation& t, bool keepBoundary,
                                         std::int64_t& count) {
  std::vector<bool> used(t.points.size(), false);
  for (const TriangleVertices& v : t.triangles)
    for (std::uint32_t k : v) used[k] = true;
  const std::vector<bool> fixed =
      keepBoundary ? boundaryVertices(t) : std::vector<bool>(t.points.size(), false);
  std::vector<std::int64_t> unknown(t.points.size(), kFixed);
  count = 0;
  for (std::size_t i = 0; i < t.points.size(); ++i)
    if (used[i] && !fixed[i]) unknown[i] = count++;
  return unknown;
}

// One step of the flow; false when the system could not be factored.
bool implicitStep(Triangulation& t, const std::vector<std::int64_t>& unknown, std::int64_t count,
                  double dt) {
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(count, 3);
  auto row = [](Vec3 p) { return Eigen::RowVector3d(p.x, p.y, p.z); };
  for (std::uint32_t tri = 0; tri < t.triangles.size(); ++tri) {
    const TriangleVertices& v = t.triangles[tri];
    const std::array<double, 3> cot = cornerCotangents(t, tri);
    const double lumpedArea = triangleArea(t, tri) / 3;
    for (int k = 0; k < 3; ++k) {
      if (const std::int64_t i = unknown[v[k]]; i != kFixed) {
        entries.emplace_back(i, i, lumpedArea);
        rhs.row(i) += lumpedArea * row(t.points[v[k]]);
      }
      // The edge opposite corner k, with stiffness cot / 2 between its ends.
      const double w = dt * cot[k] / 2;
      for (const auto& [a, b] : {std::pair{v[(k + 1) % 3], v[(k + 2) % 3]},
                                std::pair{v[(k + 2) % 3], v[(k + 1) % 3]}}) {
        const std::int64_t i = unknown[a], j = unknown[b];
        if (i == kFixed) continue;
        entries.emplace_back(i, i, w);
        if (j != kFixed)
          entries.emplace_back(i, j, -w);
        else
          rhs.row(i) += w * row(t.points[b]);
      }
    }
  }
  Eigen::SparseMatrix<double> system(count, count);
  system.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::MatrixX3d x = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !x.allFinite()) return false;
  for (std::size_t p = 0; p < t.points.size(); ++p)
    if (const std::int64_t i = unknown[p]; i != kFixed) t.points[p] = {x(i, 0), x(i, 1), x(i, 2)};
  return true;
}

void restoreVolume(Triangulation& t, double volume) {
  const double now = enclosedVolume(t);
  if (now == 0 || (now > 0) != (volume > 0)) return;
  std::vector<bool> used(t.points.size(), false);
  for (const TriangleVertices& v : t.triangles)
    for (std::uint32_t k : v) used[k] = true;
  Vec3 centroid;
  double count = 0;
  for (std::size_t i = 0; i < t.points.size(); ++i)
    if (used[i]) centroid += t.points[i], ++count;
  centroid = centroid / count;
  const double scale = std::cbrt(volume / now);
  for (std::size_t i = 0; i < t.points.size(); ++i)
    if (used[i]) t.points[i] = centroid + scale * (t.points[i] - centroid);
}

}  // namespace

void fair(Triangulation& t, const FairingOptions& options) {
  if (options.iterations <= 0 || options.step <= 0 || t.triangles.empty()) return;
  std::int64_t count = 0;
  const std::vector<std::int64_t> unknown = numberUnknowns(t, options.keepBoundary, count);
  if (count == 0) return;
  const double h = meanEdgeLength(t), dt = options.step * h * h;
  const bool closed = isClosed(t);
  const double volume = closed ? enclosedVolume(t) : 0;
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    if (!implicitStep(t, unknown, count, dt)) return;
    if (closed) restoreVolume(t, volume);
  }
}

}  // namespace geomesh
