// recombineTriangles: greedy or blossom pairing of triangles into quadrangles by corner angle;
// splitPoorQuadrangles: the quadrangles below a quality cut back into triangles.
#include "mesh/quads/recombine.h"

#include "mesh/core/quality.h"
#include "mesh/quads/blossom_matching.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace geomesh {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A candidate: triangles s and t (indices in the block) joined across their shared edge.
struct Candidate {
  double quality;
  std::uint32_t s, t;
  NodeIndex quad[4];
};

// The quadrangle of triangle (a b c) and its neighbour across edge k (the triangle's edge
// from vertex k to k+1), whose vertex opposite that edge is `opposite`.
void quadOf(std::span<const NodeIndex> tri, int k, NodeIndex opposite, NodeIndex (&quad)[4]) {
  const NodeIndex a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
  quad[0] = a, quad[1] = opposite, quad[2] = b, quad[3] = c;
}

std::vector<Candidate> candidates(const Mesh& mesh, const ElementBlock& triangles,
                                  double minQuality, const std::vector<std::uint64_t>& kept) {
  // Every triangle side, sorted by edge: the two sides of an interior edge end up adjacent.
  struct Side {
    std::uint64_t key;
    std::uint32_t triangle;
    int edge;
  };
  std::vector<Side> sides;
  sides.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const auto n = triangles.element(t);
    for (int k = 0; k < 3; ++k) sides.push_back({edgeKey(n[k], n[(k + 1) % 3]), t, k});
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return a.key != b.key ? a.key < b.key : a.triangle < b.triangle;
  });
  std::vector<Candidate> result;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].key == sides[i].key) ++j;
    const bool interior = j - i == 2;  // else a boundary or non-manifold edge
    const Side* halves = &sides[i];
    i = j;
    if (!interior || std::binary_search(kept.begin(), kept.end(), halves[0].key)) continue;
    const auto s = triangles.element(halves[0].triangle);
    const auto t = triangles.element(halves[1].triangle);
    Candidate c{0, halves[0].triangle, halves[1].triangle, {}};
    quadOf(s, halves[0].edge, t[(halves[1].edge + 2) % 3], c.quad);
    const Vec3 p0 = mesh.node(s[0]), p1 = mesh.node(s[1]), p2 = mesh.node(s[2]);
    const Vec3 q0 = mesh.node(t[0]), q1 = mesh.node(t[1]), q2 = mesh.node(t[2]);
    const Vec3 normal = cross(p1 - p0, p2 - p0) + cross(q1 - q0, q2 - q0);
    c.quality = quadAngleQuality(mesh.node(c.quad[0]), mesh.node(c.quad[1]), mesh.node(c.quad[2]),
                                 mesh.node(c.quad[3]), normal);
    if (c.quality >= minQuality) result.push_back(c);
  }
  // Best first; ties broken by triangle indices.
  std::sort(result.begin(), result.end(), [](const Candidate& x, const Candidate& y) {
    if (x.quality != y.quality) return x.quality > y.quality;
    if (x.s != y.s) return x.s < y.s;
    return x.t < y.t;
  });
  return result;
}

double cornerAngle(Vec3 prev, Vec3 at, Vec3 next) {
  const Vec3 u = prev - at, v = next - at;
  const double nu = norm(u), nv = norm(v);
  if (!(nu > 0) || !(nv > 0)) return 0;
  return std::acos(std::clamp(dot(u, v) / (nu * nv), -1.0, 1.0));
}

// Greedy: best quality first.
std::vector<std::uint8_t> greedyChoice(const std::vector<Candidate>& ranked,
                                       std::size_t triangleCount) {
  std::vector<std::uint8_t> paired(triangleCount, 0), chosen(ranked.size(), 0);
  for (std::size_t k = 0; k < ranked.size(); ++k) {
    const Candidate& c = ranked[k];
    if (paired[c.s] || paired[c.t]) continue;
    paired[c.s] = paired[c.t] = 1;
    chosen[k] = 1;
  }
  return chosen;
}

// Blossom: the greedy pairs, completed into a maximum-cardinality matching by Edmonds'
// blossom algorithm (augmenting paths re-pair a few triangles so that as few as possible
// stay alone).
std::vector<std::uint8_t> blossomChoice(const std::vector<Candidate>& ranked,
                                        std::size_t triangleCount) {
  std::vector<std::uint32_t> ends;
  ends.reserve(2 * ranked.size());
  for (const Candidate& c : ranked) ends.insert(ends.end(), {c.s, c.t});
  return maximumMatching(static_cast<std::uint32_t>(triangleCount), ends,
                         greedyChoice(ranked, triangleCount));
}

}  // namespace

double quadAngleQuality(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 normal) {
  const Vec3 p[4] = {a, b, c, d};
  double worst = 0;
  for (int k = 0; k < 4; ++k) {
    const Vec3 prev = p[(k + 3) % 4], at = p[k], next = p[(k + 1) % 4];
    const Vec3 turn = cross(at - prev, next - at);
    const double scale = norm(at - prev) * norm(next - at);
    if (!(dot(turn, normal) > 1e-12 * scale * norm(normal))) return -1;
    worst = std::max(worst, std::abs(cornerAngle(prev, at, next) - kPi / 2));
  }
  return 1 - worst / (kPi / 2);
}

std::size_t recombineTriangles(const Mesh& mesh, EntityMesh& em, RecombinationAlgorithm algorithm,
                               const std::vector<std::uint64_t>& keptEdges) {
  ElementBlock* block = nullptr;
  for (ElementBlock& b : em.blocks)
    if (b.type == ElementType::Triangle3) block = &b;
  if (!block || block->size() < 2) return 0;
  const std::vector<Candidate> ranked = candidates(mesh, *block, kMinQuadQuality, keptEdges);
  const std::vector<std::uint8_t> chosen = algorithm == RecombinationAlgorithm::Blossom
                                               ? blossomChoice(ranked, block->size())
                                               : greedyChoice(ranked, block->size());
  std::vector<std::uint8_t> paired(block->size(), 0);
  std::vector<NodeIndex> quads;
  for (std::size_t k = 0; k < ranked.size(); ++k) {
    if (!chosen[k]) continue;
    const Candidate& c = ranked[k];
    paired[c.s] = paired[c.t] = 1;
    quads.insert(quads.end(), std::begin(c.quad), std::end(c.quad));
  }
  std::vector<NodeIndex> left;
  for (std::uint32_t t = 0; t < block->size(); ++t)
    if (!paired[t]) {
      const auto n = block->element(t);
      left.insert(left.end(), n.begin(), n.end());
    }
  block->nodes = std::move(left);
  const std::size_t count = quads.size() / 4;
  if (count > 0) em.block(ElementType::Quad4).nodes = std::move(quads);
  em.blocks.erase(std::remove_if(em.blocks.begin(), em.blocks.end(),
                                 [](const ElementBlock& b) { return b.nodes.empty(); }),
                  em.blocks.end());
  return count;
}

std::size_t splitPoorQuadrangles(const Mesh& mesh, EntityMesh& em, double minQuality) {
  ElementBlock* quads = nullptr;
  for (ElementBlock& b : em.blocks)
    if (b.type == ElementType::Quad4) quads = &b;
  if (!quads || !(minQuality > 0)) return 0;
  std::vector<NodeIndex> keptQuads, triangles;
  std::size_t split = 0;
  for (std::size_t e = 0; e < quads->size(); ++e) {
    const auto n = quads->element(e);
    const Vec3 a = mesh.node(n[0]), b = mesh.node(n[1]), c = mesh.node(n[2]), d = mesh.node(n[3]);
    const Vec3 up = cross(c - a, d - b);  // twice the polygon's area vector
    if (quadAngleQuality(a, b, c, d, up) >= minQuality) {
      keptQuads.insert(keptQuads.end(), n.begin(), n.end());
      continue;
    }
    // The diagonal whose two triangles are both turned along the quadrangle and the better
    // shaped.
    auto worst = [&](Vec3 p, Vec3 q, Vec3 r, Vec3 s, Vec3 t, Vec3 u) {
      if (!(dot(cross(q - p, r - p), up) > 0) || !(dot(cross(t - s, u - s), up) > 0)) return -1.0;
      return std::min(triangleGamma(p, q, r), triangleGamma(s, t, u));
    };
    const double alongAC = worst(a, b, c, a, c, d), alongBD = worst(a, b, d, b, c, d);
    if (alongAC >= alongBD)
      triangles.insert(triangles.end(), {n[0], n[1], n[2], n[0], n[2], n[3]});
    else
      triangles.insert(triangles.end(), {n[0], n[1], n[3], n[1], n[2], n[3]});
    ++split;
  }
  if (split == 0) return 0;
  quads->nodes = std::move(keptQuads);
  ElementBlock& t = em.block(ElementType::Triangle3);
  t.nodes.insert(t.nodes.end(), triangles.begin(), triangles.end());
  em.blocks.erase(std::remove_if(em.blocks.begin(), em.blocks.end(),
                                 [](const ElementBlock& b) { return b.nodes.empty(); }),
                  em.blocks.end());
  return split;
}

}  // namespace geomesh
