// shrinkLayer: facing parts of a layer kept apart, inverted layer elements shortened away.
#include "mesh/structured/layer_shrinking.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace geomesh {
namespace {

constexpr double kGapShare = 0.45;  // of the gap between facing nodes, per column
constexpr double kFacing = 0.5;     // cosine: the other node lies within 60 degrees ahead
constexpr double kShorten = 0.7;
constexpr int kShortenRounds = 12;

double det(Vec3 a, Vec3 b, Vec3 c) { return dot(a, cross(b, c)); }

struct Columns {
  const Mesh& mesh;
  const std::unordered_map<NodeIndex, Vec3>& normals;
  const std::unordered_map<NodeIndex, double>& height;  // per node, signed
  std::unordered_map<NodeIndex, double>& factor;

  Vec3 top(NodeIndex n) const {
    return mesh.node(n) + height.at(n) * factor.at(n) * normals.at(n);
  }

  // Every corner of the element over the face, at its bottom and at its top, turns the way
  // the face's layer grows (`sign`).
  bool valid(std::span<const NodeIndex> f, double sign) const {
    const std::size_t n = f.size();
    if (n == 2) return validQuadrangle(f[0], f[1], sign);
    for (std::size_t i = 0; i < n; ++i) {
      const NodeIndex a = f[i], next = f[(i + 1) % n], previous = f[(i + n - 1) % n];
      const Vec3 p = mesh.node(a), q = top(a);
      if (!(sign * det(mesh.node(next) - p, mesh.node(previous) - p, q - p) > 0)) return false;
      if (!(sign * det(top(next) - q, top(previous) - q, q - p) > 0)) return false;
    }
    return true;
  }

  // A segment's layer in the xy-plane: its normal is the tangent x z, so the quadrangle over
  // it turns clockwise about z where the height is positive.
  bool validQuadrangle(NodeIndex a, NodeIndex b, double sign) const {
    const Vec3 pa = mesh.node(a), pb = mesh.node(b), qa = top(a), qb = top(b);
    const Vec3 z{0, 0, 1};
    auto turns = [&](Vec3 u, Vec3 v) { return -sign * dot(cross(u, v), z) > 0; };
    return turns(pb - pa, qa - pa) && turns(pb - pa, qb - pb) && turns(qb - qa, qa - pa) &&
           turns(qb - qa, qb - pb);
  }
};

std::set<std::pair<NodeIndex, NodeIndex>> faceNeighbours(const LayerFaces& faces) {
  std::set<std::pair<NodeIndex, NodeIndex>> pairs;
  std::size_t at = 0;
  for (unsigned char size : faces.sizes) {
    for (std::size_t i = 0; i < size; ++i)
      for (std::size_t j = 0; j < size; ++j)
        if (i != j) pairs.insert({faces.nodes[at + i], faces.nodes[at + j]});
    at += size;
  }
  return pairs;
}

// (1): nodes of the layer closer than two heights, each ahead of the other the way its
// column grows.
void keepFacingPartsApart(const Mesh& mesh, const LayerFaces& faces,
                          const std::unordered_map<NodeIndex, Vec3>& normals,
                          const std::unordered_map<NodeIndex, double>& height,
                          std::unordered_map<NodeIndex, double>& factor) {
  double reach = 0;
  for (const auto& [n, h] : height) reach = std::max(reach, 2 * std::abs(h));
  if (!(reach > 0)) return;
  auto growth = [&](NodeIndex n) {
    return (height.at(n) > 0 ? 1.0 : height.at(n) < 0 ? -1.0 : 0.0) * normals.at(n);
  };
  using Cell = std::tuple<long long, long long, long long>;
  auto cellOf = [&](Vec3 p) {
    return Cell{std::llround(std::floor(p.x / reach)), std::llround(std::floor(p.y / reach)),
                std::llround(std::floor(p.z / reach))};
  };
  std::map<Cell, std::vector<NodeIndex>> cells;
  std::vector<NodeIndex> nodes;
  for (const auto& [n, normal] : normals) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  for (NodeIndex n : nodes) cells[cellOf(mesh.node(n))].push_back(n);
  const auto neighbours = faceNeighbours(faces);
  for (NodeIndex a : nodes) {
    const Vec3 p = mesh.node(a);
    const auto [i, j, k] = cellOf(p);
    for (long long di = -1; di <= 1; ++di)
      for (long long dj = -1; dj <= 1; ++dj)
        for (long long dk = -1; dk <= 1; ++dk) {
          const auto it = cells.find({i + di, j + dj, k + dk});
          if (it == cells.end()) continue;
          for (NodeIndex b : it->second) {
            if (b <= a || neighbours.contains({a, b})) continue;
            const Vec3 gap = mesh.node(b) - p;
            const double d = norm(gap);
            if (!(d < reach) || d == 0) continue;
            if (dot(growth(a), gap) <= kFacing * d || dot(growth(b), -1.0 * gap) <= kFacing * d)
              continue;
            factor[a] = std::min(factor[a], kGapShare * d / std::abs(height.at(a)));
            factor[b] = std::min(factor[b], kGapShare * d / std::abs(height.at(b)));
          }
        }
  }
}

// (2): the columns of every face whose element would be inverted, shortened in rounds.
void shortenInvertedElements(const LayerFaces& faces, const Columns& columns) {
  for (int round = 0; round < kShortenRounds; ++round) {
    std::set<NodeIndex> shorten;
    std::size_t at = 0;
    for (std::size_t k = 0; k < faces.sizes.size(); ++k) {
      const std::span<const NodeIndex> f(faces.nodes.data() + at, faces.sizes[k]);
      const double h = faces.heights[k];
      if (h != 0 && !columns.valid(f, h > 0 ? 1 : -1)) shorten.insert(f.begin(), f.end());
      at += faces.sizes[k];
    }
    if (shorten.empty()) return;
    for (NodeIndex n : shorten) columns.factor[n] *= kShorten;
  }
}

}  // namespace

LayerShrinking shrinkLayer(const Mesh& mesh, const LayerFaces& faces,
                           const std::unordered_map<NodeIndex, Vec3>& normals) {
  LayerShrinking s;
  std::unordered_map<NodeIndex, double> height;
  for (const auto& [n, normal] : normals) {
    s.factor[n] = 1;
    height[n] = 0;
  }
  std::size_t at = 0;
  for (std::size_t k = 0; k < faces.sizes.size(); ++k) {
    for (std::size_t i = 0; i < faces.sizes[k]; ++i) {
      const auto h = height.find(faces.nodes[at + i]);
      if (h != height.end() && std::abs(faces.heights[k]) > std::abs(h->second))
        h->second = faces.heights[k];
    }
    at += faces.sizes[k];
  }
  keepFacingPartsApart(mesh, faces, normals, height, s.factor);
  shortenInvertedElements(faces, Columns{mesh, normals, height, s.factor});
  for (const auto& [n, f] : s.factor) {
    if (f < 1) ++s.shrunk;
    if (f < s.smallest || (f == s.smallest && f < 1 && n < s.where)) {
      s.smallest = f;
      s.where = n;
    }
  }
  if (s.shrunk > 0) s.at = mesh.node(s.where);
  return s;
}

}  // namespace geomesh
