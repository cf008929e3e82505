// subdivideIntoQuadrangles and subdivideIntoHexahedra: curves cut at their middles, triangles
// into 3 quadrangles, quadrangles into 4, tetrahedra into 4 hexahedra, prisms into 6, hexahedra
// into 8.
#include "mesh/quads/subdivision.h"

#include "mesh/core/element_corners.h"
#include "mesh/quads/recombine.h"

#include <algorithm>
#include <array>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace geomesh {
namespace {

using EdgeMiddles = std::unordered_map<std::uint64_t, NodeIndex>;

// The centre node of each face, by its corners sorted (a triangle's padded with kNoNode).
constexpr NodeIndex kNoNode = ~NodeIndex{0};
using FaceKey = std::array<NodeIndex, 4>;
using FaceCentres = std::map<FaceKey, NodeIndex>;

FaceKey faceKey(std::span<const NodeIndex> corners) {
  FaceKey key{kNoNode, kNoNode, kNoNode, kNoNode};
  std::copy(corners.begin(), corners.end(), key.begin());
  std::sort(key.begin(), key.end());
  return key;
}

// Cuts every segment of the curve at its parametric middle.
void splitCurve(const ModelCurve& curve, Mesh& mesh, EdgeMiddles& middles) {
  EntityMesh& em = mesh.entity({1, curve.tag});
  const ElementBlock* lines = em.findBlock(ElementType::Line2);
  if (!lines || lines->size() == 0) return;
  const bool haveParameters = curve.geometry && em.parametric.size() == em.nodes.size();
  std::vector<double> params;
  if (haveParameters) {
    const Interval range = curve.geometry->range();
    params.push_back(range.min);
    params.insert(params.end(), em.parametric.begin(), em.parametric.end());
    params.push_back(range.max);
  }
  std::vector<NodeIndex> nodes, segments;
  std::vector<double> parametric;
  for (std::size_t k = 0; k < lines->size(); ++k) {
    const NodeIndex a = lines->element(k)[0], b = lines->element(k)[1];
    NodeIndex middle;
    if (haveParameters && params.size() == lines->size() + 1) {
      const double t = 0.5 * (params[k] + params[k + 1]);
      middle = mesh.addNode(curve.geometry->point(t));
      parametric.push_back(t);
    } else {
      middle = mesh.addNode(0.5 * (mesh.node(a) + mesh.node(b)));
    }
    middles[edgeKey(a, b)] = middle;
    nodes.push_back(middle);
    if (k + 1 < lines->size()) {
      nodes.push_back(b);
      if (haveParameters && params.size() == lines->size() + 1) parametric.push_back(params[k + 1]);
    }
    segments.insert(segments.end(), {a, middle, middle, b});
  }
  em.nodes = std::move(nodes);
  em.parametric =
      parametric.size() == em.nodes.size() ? std::move(parametric) : std::vector<double>{};
  em.block(ElementType::Line2).nodes = std::move(segments);
}

class SurfaceSplitter {
 public:
  SurfaceSplitter(const ModelSurface& s, Mesh& mesh, EdgeMiddles& middles, FaceCentres& centres)
      : surface_(s),
        mesh_(mesh),
        middles_(middles),
        centres_(centres),
        em_(mesh.entity({2, s.tag})) {}

  void run() {
    std::vector<NodeIndex> quads;
    for (const ElementType type : {ElementType::Triangle3, ElementType::Quad4}) {
      const ElementBlock* block = em_.findBlock(type);
      if (!block) continue;
      const std::size_t n = static_cast<std::size_t>(nodeCount(type));
      for (std::size_t e = 0; e < block->size(); ++e) {
        const auto v = block->element(e);
        Vec3 sum{0, 0, 0};
        for (NodeIndex x : v) sum = sum + mesh_.node(x);
        const NodeIndex center = addSurfaceNode(sum / static_cast<double>(n));
        centres_[faceKey(v)] = center;
        for (std::size_t k = 0; k < n; ++k) {
          const NodeIndex prev = v[(k + n - 1) % n], at = v[k], next = v[(k + 1) % n];
          quads.insert(quads.end(), {at, middle(at, next), center, middle(prev, at)});
        }
      }
    }
    em_.blocks.clear();
    em_.block(ElementType::Quad4).nodes = std::move(quads);
  }

 private:
  NodeIndex addSurfaceNode(Vec3 x) {
    if (!surface_.geometry) {
      const NodeIndex n = mesh_.addNode(x);
      em_.nodes.push_back(n);
      em_.parametric.clear();
      return n;
    }
    const Vec2 uv = surface_.geometry->project(x);
    const NodeIndex n = mesh_.addNode(surface_.geometry->point(uv));
    const bool keepParameters = em_.parametric.size() == 2 * em_.nodes.size();
    em_.nodes.push_back(n);
    if (keepParameters) em_.parametric.insert(em_.parametric.end(), {uv.u, uv.v});
    return n;
  }
  NodeIndex middle(NodeIndex a, NodeIndex b) {
    const auto [it, inserted] = middles_.try_emplace(edgeKey(a, b), 0);
    if (inserted) it->second = addSurfaceNode(0.5 * (mesh_.node(a) + mesh_.node(b)));
    return it->second;
  }

  const ModelSurface& surface_;
  Mesh& mesh_;
  EdgeMiddles& middles_;
  FaceCentres& centres_;
  EntityMesh& em_;
};

void splitCurvesAndSurfaces(const Model& model, Mesh& mesh, EdgeMiddles& middles,
                            FaceCentres& centres) {
  for (const auto& entry : model.curves()) splitCurve(entry.second, mesh, middles);
  for (const auto& entry : model.surfaces())
    if (mesh.find({2, entry.first})) {
      SurfaceSplitter(entry.second, mesh, middles, centres).run();
      mesh.entity({2, entry.first}).layer.reset();  // its elements are split apart
    }
}

// A volume element's corners (cornerNeighbours) and its faces.
struct CellShape {
  std::span<const std::array<int, 4>> corners;  // (corner, a, b, c)
  std::vector<std::vector<int>> faces;
};

const CellShape& cellShape(ElementType type) {
  static const CellShape tet{cornerNeighbours(ElementType::Tet4),
                             {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}};
  static const CellShape prism{cornerNeighbours(ElementType::Prism6),
                               {{0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {0, 2, 5, 3}}};
  static const CellShape hex{
      cornerNeighbours(ElementType::Hex8),
      {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 3, 7, 4}}};
  return type == ElementType::Tet4 ? tet : type == ElementType::Prism6 ? prism : hex;
}

// Splits the elements of one volume into hexahedra, one per corner: the corner, the middles of
// its three edges, the centres of its three faces and the element's centre. Middles and
// centres already made on curves and surfaces are shared; the others are new nodes of the
// volume, at the mean of their element's edge or face corners.
class VolumeSplitter {
 public:
  VolumeSplitter(Mesh& mesh, int tag, EdgeMiddles& middles, FaceCentres& centres)
      : mesh_(mesh), middles_(middles), centres_(centres), em_(mesh.entity({3, tag})) {}

  void run() {
    std::vector<NodeIndex> hexes;
    for (const ElementType type : {ElementType::Tet4, ElementType::Prism6, ElementType::Hex8}) {
      const ElementBlock* block = em_.findBlock(type);
      if (!block) continue;
      const CellShape& shape = cellShape(type);
      for (std::size_t e = 0; e < block->size(); ++e) {
        const auto v = block->element(e);
        const NodeIndex centre = addNode(v);
        for (const auto& [at, a, b, c] : shape.corners) {
          const NodeIndex x = v[at];
          hexes.insert(
              hexes.end(),
              {x, middle(x, v[a]), faceCentre(shape, v, at, a, b), middle(x, v[b]), middle(x, v[c]),
               faceCentre(shape, v, at, a, c), centre, faceCentre(shape, v, at, b, c)});
        }
      }
    }
    em_.blocks.erase(std::remove_if(em_.blocks.begin(), em_.blocks.end(),
                                    [](const ElementBlock& b) { return dimension(b.type) == 3; }),
                     em_.blocks.end());
    if (!hexes.empty()) em_.block(ElementType::Hex8).nodes = std::move(hexes);
  }

 private:
  NodeIndex addNode(std::span<const NodeIndex> around) {
    Vec3 sum{0, 0, 0};
    for (NodeIndex n : around) sum = sum + mesh_.node(n);
    const NodeIndex n = mesh_.addNode(sum / static_cast<double>(around.size()));
    em_.nodes.push_back(n);
    return n;
  }
  NodeIndex middle(NodeIndex a, NodeIndex b) {
    const auto [it, inserted] = middles_.try_emplace(edgeKey(a, b), 0);
    if (inserted) it->second = addNode(std::array<NodeIndex, 2>{a, b});
    return it->second;
  }
  // The centre of the element's face through corners at, a and b.
  NodeIndex faceCentre(const CellShape& shape, std::span<const NodeIndex> v, int at, int a, int b) {
    for (const std::vector<int>& face : shape.faces) {
      auto has = [&](int k) { return std::find(face.begin(), face.end(), k) != face.end(); };
      if (!has(at) || !has(a) || !has(b)) continue;
      std::vector<NodeIndex> corners;
      for (int k : face) corners.push_back(v[k]);
      const auto [it, inserted] = centres_.try_emplace(faceKey(corners), 0);
      if (inserted) it->second = addNode(corners);
      return it->second;
    }
    return kNoNode;  // not reached: the tables list every corner's faces
  }

  Mesh& mesh_;
  EdgeMiddles& middles_;
  FaceCentres& centres_;
  EntityMesh& em_;
};

}  // namespace

void subdivideIntoQuadrangles(const Model& model, Mesh& mesh) {
  EdgeMiddles middles;
  FaceCentres centres;
  splitCurvesAndSurfaces(model, mesh, middles, centres);
}

std::string subdivideIntoHexahedra(const Model& model, Mesh& mesh) {
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& block : em.blocks) {
      if (block.type == ElementType::Pyramid5) return "a pyramid has no split into a few hexahedra";
      if (block.nodes.empty() || block.type == ElementType::Point1 ||
          block.type == ElementType::Line2 || block.type == ElementType::Triangle3 ||
          block.type == ElementType::Quad4 || block.type == ElementType::Tet4 ||
          block.type == ElementType::Prism6 || block.type == ElementType::Hex8)
        continue;
      return "only first-order meshes are split";
    }
  EdgeMiddles middles;
  FaceCentres centres;
  splitCurvesAndSurfaces(model, mesh, middles, centres);
  for (const auto& entry : model.volumes())
    if (mesh.find({3, entry.first})) VolumeSplitter(mesh, entry.first, middles, centres).run();
  return {};
}

}  // namespace geomesh
