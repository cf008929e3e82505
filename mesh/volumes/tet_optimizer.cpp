// TetOptimizer: edge removal by Klincsek's programme, 2-3 flips and smoothing of tetrahedra.
#include "mesh/volumes/tet_optimizer.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh/core/predicates.h"
#include "mesh/core/quality.h"

namespace geomesh {

namespace {

using Tet = std::array<int, 4>;   // local node indices, positively oriented
using Face = std::array<int, 3>;  // local node indices, sorted

constexpr int kPasses = 8;
constexpr std::size_t kMaxRing = 9;  // larger rings around an edge are rare and rarely improve
constexpr int kSmoothingSteps = 6;
constexpr double kGain = 1e-6;  // smallest quality gain worth a change: no cycling on noise

std::uint64_t edgeKey(int a, int b) {
  return std::uint64_t(std::min(a, b)) << 32 | std::uint32_t(std::max(a, b));
}

Face faceKey(int a, int b, int c) {
  Face f{a, b, c};
  std::sort(f.begin(), f.end());
  return f;
}

// Gamma of a tetrahedron, -1 when it is flat or inverted (exact orientation test): the
// measure the threshold is in.
double quality(const std::vector<Vec3>& xyz, const Tet& t) {
  const Vec3 a = xyz[t[0]], b = xyz[t[1]], c = xyz[t[2]], d = xyz[t[3]];
  if (orient3d(a, b, c, d) <= 0) return -1;
  return tetGamma(a, b, c, d);
}

// The cubed mean ratio, -1 when flat or inverted: the measure changes are compared in (it
// ranks tetrahedra much as gamma does, at a fraction of the cost); the exact orientation test
// only where the measure's sign is in doubt.
double shape(const std::vector<Vec3>& xyz, const Tet& t) {
  const Vec3 a = xyz[t[0]], b = xyz[t[1]], c = xyz[t[2]], d = xyz[t[3]];
  const double measure = tetMeanRatioCubed(a, b, c, d);
  if (measure > kSureMeanRatioCubed) return measure;
  if (measure < -kSureMeanRatioCubed || orient3d(a, b, c, d) <= 0) return -1;
  return std::max(measure, 0.0);
}

// Gamma, needed only to compare with the threshold: a tetrahedron whose mean ratio is 0.8 or
// more (`shapeOfT` its shape) has a gamma above 0.66 (sampled over many shapes), so below
// thresholds up to 0.6 its gamma is not computed (1 stands for it).
double gammaFor(const std::vector<Vec3>& xyz, const Tet& t, double shapeOfT, double threshold) {
  constexpr double kGoodShape = 0.8 * 0.8 * 0.8;  // mean ratio 0.8, cubed
  if (threshold <= 0.6 && shapeOfT >= kGoodShape) return 1;
  return quality(xyz, t);
}

// A tetrahedral mesh being modified in place: dead tetrahedra stay as holes in the arrays, and
// each node knows the tetrahedra around it, which is all the adjacency the local operations
// need (a face's neighbour is found among the tetrahedra of one of its nodes). The kept faces
// and edges (sorted) are never flipped away.
class TetOptimizer {
 public:
  TetOptimizer(std::vector<Vec3>& xyz, std::vector<char> movable, std::vector<Tet> tets,
               double threshold, std::vector<Face> keptFaces, std::vector<std::uint64_t> keptEdges);
  TetOptimizerStats run();
  std::vector<Tet> tetrahedra() const;

 private:
  int addTet(const Tet& t);
  void removeTet(int t);
  bool improveTet(int t);
  bool removeEdge(int a, int b);
  bool swapFace(int t, int k);
  bool smoothNode(int v);
  double ballMinimum(int v, Vec3 at);

  std::vector<Vec3>& xyz_;
  std::vector<char> movable_;
  std::vector<Tet> tets_;
  std::vector<double> quality_, shape_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> around_;  // per node, its alive tetrahedra
  double threshold_;
  std::vector<Face> keptFaces_;
  std::vector<std::uint64_t> keptEdges_;
  std::vector<int> shared_;  // scratch of removeEdge: the tetrahedra around the edge
  TetOptimizerStats stats_;
};

TetOptimizer::TetOptimizer(std::vector<Vec3>& xyz, std::vector<char> movable,
                           std::vector<Tet> tets, double threshold,
                           std::vector<Face> keptFaces, std::vector<std::uint64_t> keptEdges)
    : xyz_(xyz),
      movable_(std::move(movable)),
      around_(xyz.size()),
      threshold_(threshold),
      keptFaces_(std::move(keptFaces)),
      keptEdges_(std::move(keptEdges)) {
  // Room for the tetrahedra that flips and edge removals add (dead ones are not reused): a
  // vector grown from empty would end with up to twice the capacity it needs.
  const std::size_t room = tets.size() + tets.size() / 8 + 16;
  tets_.reserve(room);
  quality_.reserve(room);
  shape_.reserve(room);
  alive_.reserve(room);
  for (const Tet& t : tets) addTet(t);
}

int TetOptimizer::addTet(const Tet& t) {
  const int index = static_cast<int>(tets_.size());
  tets_.push_back(t);
  shape_.push_back(shape(xyz_, t));
  quality_.push_back(gammaFor(xyz_, t, shape_.back(), threshold_));
  alive_.push_back(1);
  for (int n : t) around_[n].push_back(index);
  return index;
}

void TetOptimizer::removeTet(int t) {
  alive_[t] = 0;
  for (int n : tets_[t]) std::erase(around_[n], t);
}

std::vector<Tet> TetOptimizer::tetrahedra() const {
  std::vector<Tet> out;
  out.reserve(static_cast<std::size_t>(std::count(alive_.begin(), alive_.end(), 1)));
  for (std::size_t t = 0; t < tets_.size(); ++t)
    if (alive_[t]) out.push_back(tets_[t]);
  return out;
}

// The ring of tetrahedra around edge ab, as the cycle of their other nodes r0 r1 ... with each
// (a, b, ri, ri+1) positively oriented; empty when the edge is on the boundary (open ring).
std::vector<int> edgeRing(const std::vector<Vec3>& xyz, const std::vector<Tet>& tets,
                          const std::vector<int>& shared, int a, int b) {
  std::unordered_map<int, int> next;
  for (int t : shared) {
    int x = -1, y = -1;
    for (int n : tets[t])
      if (n != a && n != b) (x < 0 ? x : y) = n;
    if (orient3d(xyz[a], xyz[b], xyz[x], xyz[y]) < 0) std::swap(x, y);
    if (!next.try_emplace(x, y).second) return {};
  }
  std::vector<int> ring{next.begin()->first};
  for (std::size_t i = 1; i < shared.size(); ++i) {
    auto it = next.find(ring.back());
    if (it == next.end()) return {};
    ring.push_back(it->second);
  }
  auto last = next.find(ring.back());
  if (last == next.end() || last->second != ring.front()) return {};
  // Start at the smallest node so that the result does not depend on hash order.
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end()), ring.end());
  return ring;
}

// Best triangulation of the ring polygon for the two apexes a and b (Klincsek's dynamic
// programme, as in Shewchuk's edge removal): each triangle (ri, rj, rk), i < j < k, becomes the
// tetrahedra (a, ri, rj, rk) and (b, ri, rk, rj). Returns the worst quality of the best one
// and the tetrahedra.
std::pair<double, std::vector<Tet>> triangulateRing(const std::vector<Vec3>& xyz,
                                                    const std::vector<int>& ring, int a, int b) {
  const std::size_t n = ring.size();
  // best[i * n + j]: polygon ri..rj; 2: empty. Rings have at most kMaxRing nodes: the tables
  // live on the stack, as this runs for most edges of the poor tetrahedra.
  std::array<double, kMaxRing * kMaxRing> best;
  std::array<std::size_t, kMaxRing * kMaxRing> split;
  std::fill(best.begin(), best.begin() + std::ptrdiff_t(n * n), 2.0);
  std::fill(split.begin(), split.begin() + std::ptrdiff_t(n * n), 0);
  auto triangle = [&](std::size_t i, std::size_t j, std::size_t k) {
    return std::min(shape(xyz, {a, ring[i], ring[j], ring[k]}),
                    shape(xyz, {b, ring[i], ring[k], ring[j]}));
  };
  for (std::size_t width = 2; width < n; ++width)
    for (std::size_t i = 0; i + width < n; ++i) {
      const std::size_t j = i + width;
      double& q = best[i * n + j];
      q = -2;
      for (std::size_t k = i + 1; k < j; ++k) {
        const double c = std::min({best[i * n + k], best[k * n + j], triangle(i, k, j)});
        if (c > q) q = c, split[i * n + j] = k;
      }
    }
  std::vector<Tet> tets;
  std::vector<std::pair<std::size_t, std::size_t>> todo{{0, n - 1}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    if (j - i < 2) continue;
    const std::size_t k = split[i * n + j];
    tets.push_back({a, ring[i], ring[k], ring[j]});
    tets.push_back({b, ring[i], ring[j], ring[k]});
    todo.emplace_back(i, k);
    todo.emplace_back(k, j);
  }
  return {best[n - 1], std::move(tets)};
}

// Removing edge ab only takes out the faces around it: a kept face has kept edges.
bool TetOptimizer::removeEdge(int a, int b) {
  if (std::binary_search(keptEdges_.begin(), keptEdges_.end(), edgeKey(a, b))) return false;
  std::vector<int>& shared = shared_;
  shared.clear();
  for (int t : around_[a])
    if (std::find(tets_[t].begin(), tets_[t].end(), b) != tets_[t].end()) shared.push_back(t);
  if (shared.size() < 3 || shared.size() > kMaxRing) return false;
  const std::vector<int> ring = edgeRing(xyz_, tets_, shared, a, b);
  if (ring.empty()) return false;
  double before = 2;
  for (int t : shared) before = std::min(before, shape_[t]);
  auto [after, replacement] = triangulateRing(xyz_, ring, a, b);
  if (!(after > before + kGain)) return false;
  for (int t : shared) removeTet(t);
  for (const Tet& t : replacement) addTet(t);
  ++stats_.edgeRemovals;
  return true;
}

// 2-3 flip of the face of t opposite its corner k, when the face is shared with another
// tetrahedron: the two become three around the edge joining their apexes.
bool TetOptimizer::swapFace(int t, int k) {
  const Tet& tet = tets_[t];
  // (p, q, r) oriented so that the apex d lies on its positive side.
  int p = tet[(k + 1) % 4], q = tet[(k + 2) % 4], r = tet[(k + 3) % 4];
  const int d = tet[k];
  if (orient3d(xyz_[p], xyz_[q], xyz_[r], xyz_[d]) < 0) std::swap(p, q);
  if (std::binary_search(keptFaces_.begin(), keptFaces_.end(), faceKey(p, q, r))) return false;
  int other = -1;
  for (int u : around_[p]) {
    const Tet& s = tets_[u];
    if (u != t && std::find(s.begin(), s.end(), q) != s.end() &&
        std::find(s.begin(), s.end(), r) != s.end())
      other = u;
  }
  if (other < 0) return false;  // a boundary face
  int e = -1;
  for (int n : tets_[other])
    if (n != p && n != q && n != r) e = n;
  const std::array<Tet, 3> replacement{Tet{p, q, e, d}, Tet{q, r, e, d}, Tet{r, p, e, d}};
  double after = 2;
  for (const Tet& s : replacement) after = std::min(after, shape(xyz_, s));
  if (!(after > std::min(shape_[t], shape_[other]) + kGain)) return false;
  removeTet(t);
  removeTet(other);
  for (const Tet& s : replacement) addTet(s);
  ++stats_.faceSwaps;
  return true;
}

double TetOptimizer::ballMinimum(int v, Vec3 at) {
  const Vec3 saved = xyz_[v];
  xyz_[v] = at;
  double worst = 2;
  for (int t : around_[v]) worst = std::min(worst, shape(xyz_, tets_[t]));
  xyz_[v] = saved;
  return worst;
}

// Moves v to raise the worst quality of its ball: first towards the centroid of its
// neighbours, then by steps along the gradient of the worst tetrahedron's quality.
bool TetOptimizer::smoothNode(int v) {
  if (!movable_[v] || around_[v].empty()) return false;
  const Vec3 start = xyz_[v];
  double current = 2;
  for (int t : around_[v]) current = std::min(current, shape_[t]);
  Vec3 centroid{};
  double length = 0;
  int count = 0;
  for (int t : around_[v])
    for (int n : tets_[t])
      if (n != v) {
        centroid = centroid + xyz_[n];
        length += distance(xyz_[n], start);
        ++count;
      }
  centroid = centroid / count;
  length /= count;
  Vec3 at = start;
  for (double w : {1.0, 0.5, 0.25}) {
    const Vec3 candidate = start + w * (centroid - start);
    const double q = ballMinimum(v, candidate);
    if (q > current + kGain) {
      at = candidate, current = q;
      break;
    }
  }
  for (int step = 0; step < kSmoothingSteps; ++step) {
    int worst = around_[v].front();
    xyz_[v] = at;
    double worstShape = shape(xyz_, tets_[worst]);
    for (int t : around_[v])
      if (const double q = shape(xyz_, tets_[t]); q < worstShape) worst = t, worstShape = q;
    const double h = 1e-5 * length;
    const Vec3 axes[3] = {{h, 0, 0}, {0, h, 0}, {0, 0, h}};
    double g[3];
    for (int i = 0; i < 3; ++i) {
      xyz_[v] = at + axes[i];
      const double up = shape(xyz_, tets_[worst]);
      xyz_[v] = at - axes[i];
      g[i] = up - shape(xyz_, tets_[worst]);
    }
    xyz_[v] = start;
    const Vec3 gradient{g[0], g[1], g[2]};
    if (!(norm(gradient) > 0)) break;
    const Vec3 direction = normalized(gradient);
    bool moved = false;
    for (double s : {0.1, 0.03, 0.01, 0.003}) {
      const Vec3 candidate = at + s * length * direction;
      const double q = ballMinimum(v, candidate);
      if (q > current + kGain) {
        at = candidate, current = q, moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  if (at == start) return false;
  xyz_[v] = at;
  for (int t : around_[v]) {
    shape_[t] = shape(xyz_, tets_[t]);
    quality_[t] = gammaFor(xyz_, tets_[t], shape_[t], threshold_);
  }
  ++stats_.nodeMoves;
  return true;
}

bool TetOptimizer::improveTet(int t) {
  static constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  const Tet tet = tets_[t];
  for (const auto& e : kEdges)
    if (removeEdge(tet[e[0]], tet[e[1]])) return true;
  for (int k = 0; k < 4; ++k)
    if (swapFace(t, k)) return true;
  return false;
}

TetOptimizerStats TetOptimizer::run() {
  for (int pass = 0; pass < kPasses; ++pass) {
    std::vector<int> bad;
    for (std::size_t t = 0; t < tets_.size(); ++t)
      if (alive_[t] && quality_[t] < threshold_) bad.push_back(static_cast<int>(t));
    if (bad.empty()) break;
    std::stable_sort(bad.begin(), bad.end(),
                     [&](int x, int y) { return quality_[x] < quality_[y]; });
    bool changed = false;
    for (int t : bad)
      if (alive_[t] && quality_[t] < threshold_ && improveTet(t)) changed = true;
    std::vector<int> nodes;
    for (std::size_t t = 0; t < tets_.size(); ++t)
      if (alive_[t] && quality_[t] < threshold_)
        nodes.insert(nodes.end(), tets_[t].begin(), tets_[t].end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (int v : nodes)
      if (smoothNode(v)) changed = true;
    if (!changed) break;
  }
  return stats_;
}

}  // namespace

TetOptimizerStats optimizeTetrahedra(std::vector<Vec3>& points, std::vector<char> movable,
                                     std::vector<std::uint32_t>& tets, double threshold,
                                     std::span<const std::array<std::uint32_t, 3>> keptFaces,
                                     std::span<const std::array<std::uint32_t, 2>> keptSegments) {
  std::vector<Face> faces;
  std::vector<std::uint64_t> edges;
  for (const auto& f : keptFaces) {
    const int a = int(f[0]), b = int(f[1]), c = int(f[2]);
    faces.push_back(faceKey(a, b, c));
    edges.insert(edges.end(), {edgeKey(a, b), edgeKey(b, c), edgeKey(c, a)});
  }
  for (const auto& s : keptSegments) edges.push_back(edgeKey(int(s[0]), int(s[1])));
  std::sort(faces.begin(), faces.end());
  std::sort(edges.begin(), edges.end());
  // Only the balls of the vertices of the tetrahedra below the threshold take part: their
  // vertices move, their faces and edges change; every other tetrahedron is left as it is (the
  // faces between the two sets have a single tetrahedron in the region, and so stay). A few
  // rounds, for the poor tetrahedra a round leaves at the border of its region.
  constexpr int kRounds = 3;
  TetOptimizerStats stats;
  // The tetrahedra before `unchecked` are known not to be below the threshold: after a round,
  // those left out of its region (whose nodes did not move), so only its output is measured.
  std::size_t unchecked = 0;
  for (int round = 0; round < kRounds; ++round) {
    auto tetAt = [&](std::size_t i) {
      return Tet{int(tets[i]), int(tets[i + 1]), int(tets[i + 2]), int(tets[i + 3])};
    };
    std::vector<char> poor(points.size(), 0);
    auto touchesPoor = [&](const Tet& t) {
      return poor[t[0]] || poor[t[1]] || poor[t[2]] || poor[t[3]];
    };
    for (std::size_t i = unchecked; i < tets.size(); i += 4) {
      const Tet t = tetAt(i);
      if (gammaFor(points, t, shape(points, t), threshold) < threshold)
        for (int n : t) poor[n] = 1;
    }
    // One ring more: the neighbours of the poor tetrahedra's vertices may move too.
    std::vector<char> grown = poor;
    for (std::size_t i = 0; i < tets.size(); i += 4)
      if (const Tet t = tetAt(i); touchesPoor(t))
        for (int n : t) grown[n] = 1;
    poor.swap(grown);
    // Counted first, so that the two parts take no more memory than they hold.
    std::size_t inRegion = 0;
    for (std::size_t i = 0; i < tets.size(); i += 4) inRegion += touchesPoor(tetAt(i));
    if (inRegion == 0) break;
    std::vector<Tet> region;
    std::vector<std::uint32_t> rest;
    region.reserve(inRegion);
    rest.reserve(tets.size() - 4 * inRegion);
    for (std::size_t i = 0; i < tets.size(); i += 4) {
      const Tet t = tetAt(i);
      if (touchesPoor(t))
        region.push_back(t);
      else
        rest.insert(rest.end(), tets.begin() + std::ptrdiff_t(i),
                    tets.begin() + std::ptrdiff_t(i + 4));
    }
    std::vector<std::uint32_t>().swap(tets);  // all in `region` or `rest` now
    std::vector<char> free = movable;
    for (std::size_t n = 0; n < free.size(); ++n) free[n] = free[n] && poor[n];
    TetOptimizerStats done;
    std::vector<Tet> improved;
    {  // the optimizer's arrays are freed before the parts are joined
      TetOptimizer optimizer(points, std::move(free), std::move(region), threshold, faces, edges);
      done = optimizer.run();
      improved = optimizer.tetrahedra();
    }
    tets = std::move(rest);
    unchecked = tets.size();
    tets.reserve(tets.size() + 4 * improved.size());
    for (const Tet& t : improved)
      for (int n : t) tets.push_back(static_cast<std::uint32_t>(n));
    stats.edgeRemovals += done.edgeRemovals;
    stats.faceSwaps += done.faceSwaps;
    stats.nodeMoves += done.nodeMoves;
    if (done.edgeRemovals + done.faceSwaps + done.nodeMoves == 0) break;
  }
  return stats;
}

TetOptimizerStats optimizeTetrahedra(Mesh& mesh, EntityId volume, double threshold,
                                     const KeptInside& kept) {
  EntityMesh& em = mesh.entity(volume);
  ElementBlock* block = nullptr;
  for (ElementBlock& b : em.blocks)
    if (b.type == ElementType::Tet4) block = &b;
  if (!block || block->size() == 0) return {};
  // Local numbering in order of first use, so that the result depends on the input only.
  std::unordered_map<NodeIndex, int> local;
  std::vector<NodeIndex> global;
  std::vector<Vec3> xyz;
  std::vector<Tet> tets(block->size());
  for (std::size_t i = 0; i < block->nodes.size(); ++i) {
    const NodeIndex n = block->nodes[i];
    auto [it, inserted] = local.try_emplace(n, static_cast<int>(global.size()));
    if (inserted) {
      global.push_back(n);
      xyz.push_back(mesh.node(n));
    }
    tets[i / 4][i % 4] = it->second;
  }
  std::vector<char> movable(global.size(), 0);
  for (NodeIndex n : em.nodes)
    if (auto it = local.find(n); it != local.end()) movable[it->second] = 1;
  for (NodeIndex n : kept.fixedNodes)
    if (auto it = local.find(n); it != local.end()) movable[it->second] = 0;
  // Kept faces and edges with a node outside the tetrahedra are not among theirs anyway.
  auto at = [&](NodeIndex n) {
    const auto it = local.find(n);
    return it == local.end() ? -1 : it->second;
  };
  std::vector<std::array<std::uint32_t, 3>> keptFaces;
  std::vector<std::array<std::uint32_t, 2>> keptSegments;
  for (const auto& t : kept.triangles) {
    const int a = at(t[0]), b = at(t[1]), c = at(t[2]);
    if (a >= 0 && b >= 0 && c >= 0)
      keptFaces.push_back({std::uint32_t(a), std::uint32_t(b), std::uint32_t(c)});
  }
  for (const auto& s : kept.segments)
    if (at(s[0]) >= 0 && at(s[1]) >= 0)
      keptSegments.push_back({std::uint32_t(at(s[0])), std::uint32_t(at(s[1]))});
  std::vector<std::uint32_t> flat;
  flat.reserve(4 * tets.size());
  for (const Tet& t : tets)
    for (int n : t) flat.push_back(static_cast<std::uint32_t>(n));
  const TetOptimizerStats stats =
      optimizeTetrahedra(xyz, std::move(movable), flat, threshold, keptFaces, keptSegments);
  block->nodes.clear();
  for (std::uint32_t n : flat) block->nodes.push_back(global[n]);
  for (NodeIndex n : em.nodes)
    if (auto it = local.find(n); it != local.end()) mesh.setNode(n, xyz[it->second]);
  return stats;
}

}  // namespace geomesh
