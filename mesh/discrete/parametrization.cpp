// parametrizePatch: the patch's topology checked, then its orthogonal projection when it is
// plane, else a mean value (Floater) convex-combination map onto the unit disk.
#include "mesh/discrete/parametrization.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>
#include <utility>
#include <variant>

#include "mesh/core/predicates.h"

namespace geomesh {
namespace {

constexpr double kPlaneTolerance = 1e-6;  // relative to the patch's size
constexpr double kMaxDistortion = 1e8;

// The patch numbered locally: its vertices in order of first use by its triangles.
struct LocalPatch {
  std::vector<std::uint32_t> vertices;
  std::vector<TriangleVertices> triangles;
  std::vector<Vec3> points;
  std::vector<std::vector<std::uint32_t>> loops;
};

using Failure = std::string;

std::variant<LocalPatch, Failure> localPatch(const Triangulation& t,
                                             std::span<const std::uint32_t> triangles,
                                             std::span<const std::vector<std::uint32_t>> loops) {
  LocalPatch patch;
  std::unordered_map<std::uint32_t, std::uint32_t> localOf;
  auto local = [&](std::uint32_t v) {
    const auto [it, added] = localOf.try_emplace(v, static_cast<std::uint32_t>(localOf.size()));
    if (added) patch.vertices.push_back(v), patch.points.push_back(t.points[v]);
    return it->second;
  };
  patch.triangles.reserve(triangles.size());
  for (std::uint32_t tri : triangles) {
    const TriangleVertices& v = t.triangles[tri];
    patch.triangles.push_back({local(v[0]), local(v[1]), local(v[2])});
  }
  for (const std::vector<std::uint32_t>& loop : loops) {
    std::vector<std::uint32_t>& localLoop = patch.loops.emplace_back();
    for (std::uint32_t v : loop) {
      const auto it = localOf.find(v);
      if (it == localOf.end()) return Failure("its boundary has a vertex not on its triangles");
      localLoop.push_back(it->second);
    }
    std::vector<std::uint32_t> sorted = localLoop;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      return Failure("its boundary touches itself");
  }
  return patch;
}

// Why the patch is not a disk with loops.size() - 1 holes; empty when it is one.
std::string topologyFailure(const LocalPatch& patch) {
  if (patch.triangles.empty()) return "it has no triangles";
  if (patch.loops.empty()) return "it is closed";
  if (patch.loops[0].size() < 3) return "its outer boundary has fewer than 3 vertices";
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * patch.triangles.size());
  for (const TriangleVertices& v : patch.triangles)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  long long uniqueEdges = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i > 2) return "it has a non-manifold edge";
    ++uniqueEdges, i = j;
  }
  const long long euler = static_cast<long long>(patch.points.size()) - uniqueEdges +
                          static_cast<long long>(patch.triangles.size());
  const long long expected = 2 - static_cast<long long>(patch.loops.size());
  if (euler < expected) {
    const long long handles = (expected - euler + 1) / 2;
    return handles == 1 ? "it has a handle" : "it has " + std::to_string(handles) + " handles";
  }
  if (euler > expected) return "it is not one disk with its loops as boundary";
  return {};
}

double patchSize(std::span<const Vec3> points) {
  Vec3 lo = points[0], hi = points[0];
  for (Vec3 p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  return distance(lo, hi);
}

std::size_t foldedCount(std::span<const TriangleVertices> triangles, std::span<const Vec2> uv) {
  return static_cast<std::size_t>(std::count_if(
      triangles.begin(), triangles.end(), [&](const TriangleVertices& v) {
        return orient2d(uv[v[0]], uv[v[1]], uv[v[2]]) <= 0;
      }));
}

// The orthogonal projection onto the least-squares plane, its normal turned along the
// triangles' normals, and the plane's frame; nullopt when a vertex is off that plane.
struct PlaneProjection {
  std::vector<Vec2> uv;
  Vec3 origin, axisU, axisV;
};

std::optional<PlaneProjection> planeProjection(const LocalPatch& patch) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (Vec3 p : patch.points) centroid += Eigen::Vector3d(p.x, p.y, p.z);
  centroid /= static_cast<double>(patch.points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (Vec3 p : patch.points) {
    const Eigen::Vector3d d = Eigen::Vector3d(p.x, p.y, p.z) - centroid;
    covariance += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Matrix3d axes = solver.eigenvectors();  // by ascending eigenvalue
  const Vec3 c{centroid.x(), centroid.y(), centroid.z()};
  Vec3 normal{axes(0, 0), axes(1, 0), axes(2, 0)};
  const Vec3 e1{axes(0, 2), axes(1, 2), axes(2, 2)};
  const double tolerance = kPlaneTolerance * patchSize(patch.points);
  for (Vec3 p : patch.points)
    if (std::abs(dot(p - c, normal)) > tolerance) return std::nullopt;
  Vec3 areaVector;
  for (const TriangleVertices& v : patch.triangles)
    areaVector += cross(patch.points[v[1]] - patch.points[v[0]],
                        patch.points[v[2]] - patch.points[v[0]]);
  if (dot(areaVector, normal) < 0) normal = -normal;
  const Vec3 e2 = cross(normal, e1);
  PlaneProjection projection{{}, c, e1, e2};
  projection.uv.reserve(patch.points.size());
  for (Vec3 p : patch.points) projection.uv.push_back({dot(p - c, e1), dot(p - c, e2)});
  return projection;
}

// The patch closed into a disk: its points and triangles followed by one virtual vertex per
// hole (at the centroid of the hole's boundary) and the fan joining it to the hole's loop.
struct FilledDisk {
  std::vector<Vec3> points;
  std::vector<TriangleVertices> triangles;
};

FilledDisk filledDisk(const LocalPatch& patch) {
  FilledDisk disk{patch.points, patch.triangles};
  for (std::size_t h = 1; h < patch.loops.size(); ++h) {
    const std::vector<std::uint32_t>& loop = patch.loops[h];
    Vec3 centroid;
    for (std::uint32_t v : loop) centroid += patch.points[v];
    const auto center = static_cast<std::uint32_t>(disk.points.size());
    disk.points.push_back(centroid / static_cast<double>(loop.size()));
    // The hole lies on the loop's right: its triangles run the loop's edges backwards.
    for (std::size_t i = 0; i < loop.size(); ++i)
      disk.triangles.push_back({loop[(i + 1) % loop.size()], loop[i], center});
  }
  return disk;
}

// tan(angle / 2) for the angle between a and b, bounded where the angle nears a half turn.
double halfAngleTangent(Vec3 a, Vec3 b) {
  constexpr double kLargest = 1e6;
  const double lengths = norm(a) * norm(b);
  const double denominator = lengths + dot(a, b);
  const double numerator = norm(cross(a, b));
  if (!(lengths > 0)) return 0;
  return denominator > numerator / kLargest ? numerator / denominator : kLargest;
}

// Mean value weights: w[i][j] = (tan(alpha / 2) + tan(beta / 2)) / |xi - xj|, alpha and beta
// the angles at xi of the two triangles along edge ij. One (i, j, w) per triangle corner side.
std::vector<Eigen::Triplet<double>> meanValueWeights(const FilledDisk& disk, double size) {
  const double shortest = 1e-12 * size;
  std::vector<Eigen::Triplet<double>> weights;
  weights.reserve(6 * disk.triangles.size());
  for (const TriangleVertices& v : disk.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = v[k], j = v[(k + 1) % 3], l = v[(k + 2) % 3];
      const Vec3 toJ = disk.points[j] - disk.points[i], toL = disk.points[l] - disk.points[i];
      const double tangent = halfAngleTangent(toJ, toL);
      weights.emplace_back(i, j, tangent / std::max(norm(toJ), shortest));
      weights.emplace_back(i, l, tangent / std::max(norm(toL), shortest));
    }
  return weights;
}

// The outer loop on the unit circle, counter-clockwise, spaced by chord length.
void placeOnCircle(const LocalPatch& patch, std::vector<Vec2>& uv) {
  const std::vector<std::uint32_t>& loop = patch.loops[0];
  std::vector<double> chord(loop.size());
  double perimeter = 0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    perimeter += chord[i] =
        distance(patch.points[loop[i]], patch.points[loop[(i + 1) % loop.size()]]);
  // Coincident points still get distinct places.
  const double shortest = 1e-9 * perimeter / static_cast<double>(loop.size());
  double total = 0;
  for (double& c : chord) total += c = std::max(c, shortest);
  double along = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const double angle = 2 * std::numbers::pi * along / total;
    uv[loop[i]] = {std::cos(angle), std::sin(angle)};
    along += chord[i];
  }
}

// Solves, for every vertex off the outer loop, uv = the weighted mean of its neighbours' uv
// (Floater's convex combination); nullopt when the solver fails.
std::optional<std::vector<Vec2>> convexCombinationMap(const LocalPatch& patch) {
  const FilledDisk disk = filledDisk(patch);
  const std::size_t count = disk.points.size();
  std::vector<Vec2> uv(count);
  placeOnCircle(patch, uv);
  std::vector<int> unknown(count, 0);
  for (std::uint32_t v : patch.loops[0]) unknown[v] = -1;
  int unknowns = 0;
  for (int& u : unknown)
    if (u == 0) u = unknowns++;
  if (unknowns == 0) return uv;

  // Row sums of the weights; a row whose weights all vanish (degenerate triangles) falls back
  // to Tutte's uniform weights.
  std::vector<Eigen::Triplet<double>> weights = meanValueWeights(disk, patchSize(disk.points));
  std::vector<double> rowSum(count, 0);
  for (const auto& w : weights) rowSum[w.row()] += w.value();
  for (auto& w : weights)
    if (!(rowSum[w.row()] > 0) || !std::isfinite(rowSum[w.row()])) w = {w.row(), w.col(), 1.0};
  std::fill(rowSum.begin(), rowSum.end(), 0);
  for (const auto& w : weights) rowSum[w.row()] += w.value();

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(weights.size() + unknowns);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, 2);
  for (std::size_t v = 0; v < count; ++v)
    if (unknown[v] >= 0) entries.emplace_back(unknown[v], unknown[v], 1.0);
  for (const auto& w : weights) {
    const int row = unknown[w.row()];
    if (row < 0) continue;
    const double share = w.value() / rowSum[w.row()];
    if (unknown[w.col()] >= 0) {
      entries.emplace_back(row, unknown[w.col()], -share);
    } else {
      rhs(row, 0) += share * uv[w.col()].u;
      rhs(row, 1) += share * uv[w.col()].v;
    }
  }
  Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> solver;
  solver.compute(matrix);
  if (solver.info() != Eigen::Success) return std::nullopt;
  const Eigen::MatrixXd solution = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !solution.allFinite()) return std::nullopt;
  for (std::size_t v = 0; v < count; ++v)
    if (unknown[v] >= 0) uv[v] = {solution(unknown[v], 0), solution(unknown[v], 1)};
  uv.resize(patch.points.size());  // the virtual vertices only served the solve
  return uv;
}

// The ratio of the largest to the smallest uv-area / 3D-area over the triangles of non-zero
// area in space.
double areaDistortion(const LocalPatch& patch, std::span<const Vec2> uv) {
  double smallest = INFINITY, largest = 0;
  for (const TriangleVertices& v : patch.triangles) {
    const Vec3 a = patch.points[v[0]], b = patch.points[v[1]], c = patch.points[v[2]];
    const double area = norm(cross(b - a, c - a));
    if (!(area > 0)) continue;
    const Vec2 p = uv[v[0]], q = uv[v[1]], r = uv[v[2]];
    const double uvArea = (q.u - p.u) * (r.v - p.v) - (q.v - p.v) * (r.u - p.u);
    smallest = std::min(smallest, uvArea / area);
    largest = std::max(largest, uvArea / area);
  }
  return largest > 0 && smallest > 0 ? largest / smallest : INFINITY;
}

std::string foldedMessage(std::size_t folded) {
  return folded == 1 ? "1 triangle is folded in the plane"
                     : std::to_string(folded) + " triangles are folded in the plane";
}

ParametrizationResult mapped(LocalPatch patch, std::vector<Vec2> uv, bool planar) {
  PatchMap map{std::move(patch.vertices), std::move(patch.triangles), std::move(uv), planar};
  return {std::move(map), {}};
}

ParametrizationResult failed(std::string why) { return {std::nullopt, std::move(why)}; }

}  // namespace

ParametrizationResult parametrizePatch(const Triangulation& t,
                                       std::span<const std::uint32_t> triangles,
                                       std::span<const std::vector<std::uint32_t>> loops) {
  auto local = localPatch(t, triangles, loops);
  if (auto* why = std::get_if<Failure>(&local)) return failed(std::move(*why));
  LocalPatch& patch = std::get<LocalPatch>(local);
  if (std::string why = topologyFailure(patch); !why.empty()) return failed(std::move(why));

  if (std::optional<PlaneProjection> projection = planeProjection(patch))
    if (foldedCount(patch.triangles, projection->uv) == 0) {
      ParametrizationResult result = mapped(std::move(patch), std::move(projection->uv), true);
      result.map->origin = projection->origin;
      result.map->axisU = projection->axisU;
      result.map->axisV = projection->axisV;
      return result;
    }

  std::optional<std::vector<Vec2>> uv = convexCombinationMap(patch);
  if (!uv) return failed("its linear system could not be solved");
  if (const std::size_t folded = foldedCount(patch.triangles, *uv); folded > 0)
    return failed(foldedMessage(folded));
  if (areaDistortion(patch, *uv) > kMaxDistortion) return failed("its map is too distorted");
  return mapped(std::move(patch), std::move(*uv), false);
}

}  // namespace geomesh
