// meshTransfiniteVolume: hexahedra filling a six-faced volume from its faces' quadrangle grids.
#include "mesh/structured/transfinite_volume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

#include "mesh/curves/curve_mesher.h"
#include "mesh/quads/recombine.h"

namespace geomesh {
namespace {

using Corners = std::array<int, 8>;

// The volume's topology: its faces, curves and points, and which curve joins two points.
struct HexTopology {
  std::vector<int> surfaces;
  std::set<int> curves, points;
  std::map<std::pair<int, int>, int> curveBetween;  // (point, point), both orders -> curve
};

HexTopology topologyOf(const Model& model, int tag) {
  HexTopology t;
  for (int s : model.boundary({3, tag})) t.surfaces.push_back(std::abs(s));
  for (int s : t.surfaces)
    for (int c : model.boundary({2, s})) t.curves.insert(std::abs(c));
  for (int c : t.curves) {
    const ModelCurve* curve = model.curve(c);
    if (!curve) continue;
    t.points.insert(curve->startPoint);
    t.points.insert(curve->endPoint);
    t.curveBetween[{curve->startPoint, curve->endPoint}] = c;
    t.curveBetween[{curve->endPoint, curve->startPoint}] = c;
  }
  return t;
}

std::vector<int> neighbours(const HexTopology& t, int point) {
  std::vector<int> out;
  for (const auto& [ends, curve] : t.curveBetween)
    if (ends.first == point) out.push_back(ends.second);
  return out;
}

int commonNeighbour(const HexTopology& t, int a, int b, int except) {
  for (int n : neighbours(t, a))
    if (n != except && t.curveBetween.contains({n, b})) return n;
  return 0;
}

// The corners from the shape: the point of smallest tag, its neighbours in increasing tags as
// corners 2, 4 and 5, and the others where the faces close.
std::optional<Corners> findCorners(const HexTopology& t) {
  const int p1 = *t.points.begin();
  const std::vector<int> n = neighbours(t, p1);
  if (n.size() != 3) return std::nullopt;
  Corners c{p1, n[0], 0, n[1], n[2], 0, 0, 0};
  c[2] = commonNeighbour(t, c[1], c[3], p1);
  c[5] = commonNeighbour(t, c[1], c[4], p1);
  c[7] = commonNeighbour(t, c[3], c[4], p1);
  c[6] = commonNeighbour(t, c[2], c[5], c[1]);
  if (std::find(c.begin(), c.end(), 0) != c.end()) return std::nullopt;
  return c;
}

// The 12 edges of a hexahedron, as pairs of corner indices.
constexpr std::array<std::array<int, 2>, 12> kEdges{{{0, 1}, {1, 2}, {3, 2}, {0, 3},
                                                     {4, 5}, {5, 6}, {7, 6}, {4, 7},
                                                     {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

// The nodes of the curve from point a to point b, in that order.
std::vector<NodeIndex> chainBetween(const Model& model, const Mesh& mesh, const HexTopology& t,
                                    int a, int b) {
  const int curve = t.curveBetween.at({a, b});
  const ModelCurve* c = model.curve(curve);
  return curveNodeChain(model, mesh, c->startPoint == a ? curve : -curve);
}

// A face's nodes as a grid: rows from the side c00 -> c10 (its nodes given) across the
// quadrangles towards the opposite side, `rows` of them. Empty if the quadrangles do not make
// such a grid.
std::vector<std::vector<NodeIndex>> faceGrid(const EntityMesh& face,
                                            const std::vector<NodeIndex>& firstRow,
                                            std::size_t rows) {
  const ElementBlock* quads = face.findBlock(ElementType::Quad4);
  if (!quads || face.findBlock(ElementType::Triangle3)) return {};
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> bySide;
  for (std::uint32_t q = 0; q < quads->size(); ++q) {
    const auto n = quads->element(q);
    for (int k = 0; k < 4; ++k) bySide[edgeKey(n[k], n[(k + 1) % 4])].push_back(q);
  }
  std::vector<std::vector<NodeIndex>> grid{firstRow};
  std::vector<std::uint8_t> used(quads->size(), 0);
  while (grid.size() < rows) {
    const std::vector<NodeIndex>& row = grid.back();
    std::vector<NodeIndex> next(row.size(), 0);
    for (std::size_t i = 0; i + 1 < row.size(); ++i) {
      const auto it = bySide.find(edgeKey(row[i], row[i + 1]));
      if (it == bySide.end()) return {};
      std::optional<std::uint32_t> cell;
      for (std::uint32_t q : it->second)
        if (!used[q]) cell = q;
      if (!cell) return {};
      used[*cell] = 1;
      const auto n = quads->element(*cell);
      const int x = static_cast<int>(std::find(n.begin(), n.end(), row[i]) - n.begin());
      const bool forward = n[(x + 1) % 4] == row[i + 1];
      const NodeIndex beyondX = n[(x + (forward ? 3 : 1)) % 4];
      const NodeIndex beyondY = n[(x + 2) % 4];
      if ((next[i] != 0 && next[i] != beyondX) || (next[i + 1] != 0 && next[i + 1] != beyondY))
        return {};
      next[i] = beyondX, next[i + 1] = beyondY;
    }
    grid.push_back(std::move(next));
  }
  return grid;
}

// Cumulative arc-length fractions along a chain of nodes.
std::vector<double> fractions(const Mesh& mesh, const std::vector<NodeIndex>& chain) {
  std::vector<double> f{0};
  for (std::size_t k = 1; k < chain.size(); ++k)
    f.push_back(f.back() + distance(mesh.node(chain[k - 1]), mesh.node(chain[k])));
  for (double& x : f) x /= f.back() > 0 ? f.back() : 1;
  return f;
}

// The grid of nodes of the volume, filled face by face; index (i, j, k).
class NodeBlock {
 public:
  NodeBlock(std::size_t ni, std::size_t nj, std::size_t nk)
      : n_{ni, nj, nk}, nodes_(ni * nj * nk, kUnset) {}
  static constexpr NodeIndex kUnset = ~NodeIndex{0};
  NodeIndex& at(std::size_t i, std::size_t j, std::size_t k) {
    return nodes_[(k * n_[1] + j) * n_[0] + i];
  }
  std::size_t size(int axis) const { return n_[axis]; }

 private:
  std::array<std::size_t, 3> n_;
  std::vector<NodeIndex> nodes_;
};

// One face of the hexahedron: its corners (indices 0-7) at grid (0,0), (last,0), (0,last) of
// two of the block's axes, with the third axis fixed at 0 or its last index.
struct FaceSpec {
  int c00, c10, c01;
  int axisA, axisB, fixedAxis;
  bool atEnd;
};
constexpr std::array<FaceSpec, 6> kFaces{{{0, 1, 3, 0, 1, 2, false},
                                          {4, 5, 7, 0, 1, 2, true},
                                          {0, 1, 4, 0, 2, 1, false},
                                          {3, 2, 7, 0, 2, 1, true},
                                          {0, 3, 4, 1, 2, 0, false},
                                          {1, 2, 5, 1, 2, 0, true}}};

// The model surface whose corner points are the four given.
int surfaceWithCorners(const Model& model, const HexTopology& t, std::set<int> corners) {
  for (int s : t.surfaces) {
    std::set<int> points;
    for (int c : model.boundary({2, s})) {
      const ModelCurve* curve = model.curve(std::abs(c));
      points.insert(curve->startPoint);
      points.insert(curve->endPoint);
    }
    if (points == corners) return s;
  }
  return 0;
}

}  // namespace

std::string meshTransfiniteVolume(const Model& model, int tag, const std::vector<int>& given,
                                  Mesh& mesh) {
  const HexTopology t = topologyOf(model, tag);
  if (t.surfaces.size() != 6 || t.curves.size() != 12 || t.points.size() != 8)
    return "it is not bounded by 6 faces, 12 curves and 8 points";
  std::optional<Corners> corners;
  if (given.size() == 8) {
    corners = Corners{};
    std::copy(given.begin(), given.end(), corners->begin());
  } else {
    corners = findCorners(t);
  }
  if (!corners) return "its corners could not be found";
  const Corners& c = *corners;
  for (const auto& e : kEdges)
    if (!t.curveBetween.contains({c[e[0]], c[e[1]]}))
      return "its corners " + std::to_string(c[e[0]]) + " and " + std::to_string(c[e[1]]) +
             " are not joined by a curve";
  const std::vector<NodeIndex> alongI = chainBetween(model, mesh, t, c[0], c[1]);
  const std::vector<NodeIndex> alongJ = chainBetween(model, mesh, t, c[0], c[3]);
  const std::vector<NodeIndex> alongK = chainBetween(model, mesh, t, c[0], c[4]);
  NodeBlock block(alongI.size(), alongJ.size(), alongK.size());
  for (const FaceSpec& f : kFaces) {
    std::set<int> four{c[f.c00], c[f.c10], c[f.c01]};
    // The fourth corner: the one joined to both c10 and c01 (other than c00).
    four.insert(commonNeighbour(t, c[f.c10], c[f.c01], c[f.c00]));
    const int surface = surfaceWithCorners(model, t, four);
    const EntityMesh* em = surface ? mesh.find({2, surface}) : nullptr;
    if (!em) return "a face has no mesh";
    const std::vector<NodeIndex> firstRow = chainBetween(model, mesh, t, c[f.c00], c[f.c10]);
    const std::size_t rows = block.size(f.axisB);
    if (firstRow.size() != block.size(f.axisA))
      return "the curves of surface " + std::to_string(surface) +
             " do not have as many nodes as the opposite ones";
    const auto grid = faceGrid(*em, firstRow, rows);
    if (grid.size() != rows || grid.back().size() != firstRow.size())
      return "surface " + std::to_string(surface) +
             " is not a structured grid of quadrangles (Transfinite and Recombine Surface)";
    for (std::size_t b = 0; b < rows; ++b)
      for (std::size_t a = 0; a < firstRow.size(); ++a) {
        std::array<std::size_t, 3> index{};
        index[f.axisA] = a, index[f.axisB] = b;
        index[f.fixedAxis] = f.atEnd ? block.size(f.fixedAxis) - 1 : 0;
        NodeIndex& slot = block.at(index[0], index[1], index[2]);
        if (slot != NodeBlock::kUnset && slot != grid[b][a])
          return "the grids of its faces do not meet along its edges";
        slot = grid[b][a];
      }
  }
  // Interior nodes by transfinite interpolation of the faces, with the edges' spacing.
  const std::vector<double> u = fractions(mesh, alongI), v = fractions(mesh, alongJ),
                            w = fractions(mesh, alongK);
  const std::size_t ni = u.size() - 1, nj = v.size() - 1, nk = w.size() - 1;
  EntityMesh& em = mesh.entity({3, tag});
  em.nodes.clear();
  em.blocks.clear();
  for (std::size_t k = 1; k < nk; ++k)
    for (std::size_t j = 1; j < nj; ++j)
      for (std::size_t i = 1; i < ni; ++i) {
        auto x = [&](std::size_t a, std::size_t b, std::size_t cc) {
          return mesh.node(block.at(a, b, cc));
        };
        const double U = u[i], V = v[j], W = w[k];
        const Vec3 faces = (1 - U) * x(0, j, k) + U * x(ni, j, k) + (1 - V) * x(i, 0, k) +
                           V * x(i, nj, k) + (1 - W) * x(i, j, 0) + W * x(i, j, nk);
        const Vec3 edges =
            (1 - U) * (1 - V) * x(0, 0, k) + (1 - U) * V * x(0, nj, k) +
            U * (1 - V) * x(ni, 0, k) + U * V * x(ni, nj, k) + (1 - U) * (1 - W) * x(0, j, 0) +
            (1 - U) * W * x(0, j, nk) + U * (1 - W) * x(ni, j, 0) + U * W * x(ni, j, nk) +
            (1 - V) * (1 - W) * x(i, 0, 0) + (1 - V) * W * x(i, 0, nk) +
            V * (1 - W) * x(i, nj, 0) + V * W * x(i, nj, nk);
        const Vec3 cornersTerm =
            (1 - U) * (1 - V) * (1 - W) * x(0, 0, 0) + U * (1 - V) * (1 - W) * x(ni, 0, 0) +
            (1 - U) * V * (1 - W) * x(0, nj, 0) + U * V * (1 - W) * x(ni, nj, 0) +
            (1 - U) * (1 - V) * W * x(0, 0, nk) + U * (1 - V) * W * x(ni, 0, nk) +
            (1 - U) * V * W * x(0, nj, nk) + U * V * W * x(ni, nj, nk);
        const NodeIndex n = mesh.addNode(faces - edges + cornersTerm);
        block.at(i, j, k) = n;
        em.nodes.push_back(n);
      }
  // Hexahedra, turned so that their volumes are positive.
  ElementBlock& hexes = em.block(ElementType::Hex8);
  for (std::size_t k = 0; k < nk; ++k)
    for (std::size_t j = 0; j < nj; ++j)
      for (std::size_t i = 0; i < ni; ++i) {
        std::array<NodeIndex, 8> h{block.at(i, j, k),         block.at(i + 1, j, k),
                                   block.at(i + 1, j + 1, k), block.at(i, j + 1, k),
                                   block.at(i, j, k + 1),     block.at(i + 1, j, k + 1),
                                   block.at(i + 1, j + 1, k + 1), block.at(i, j + 1, k + 1)};
        const Vec3 o = mesh.node(h[0]);
        const double turn = dot(cross(mesh.node(h[1]) - o, mesh.node(h[3]) - o),
                                mesh.node(h[4]) - o);
        if (turn < 0) std::swap(h[1], h[3]), std::swap(h[5], h[7]);
        hexes.nodes.insert(hexes.nodes.end(), h.begin(), h.end());
      }
  return {};
}

}  // namespace geomesh
