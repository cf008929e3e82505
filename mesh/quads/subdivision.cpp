// subdivideIntoQuadrangles: curves cut at their middles, triangles into 3 quads, quads into 4.
#include "mesh/quads/subdivision.h"

#include "mesh/quads/recombine.h"

#include <unordered_map>
#include <utility>
#include <vector>

namespace geomesh {
namespace {

using EdgeMiddles = std::unordered_map<std::uint64_t, NodeIndex>;

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
  em.parametric = parametric.size() == em.nodes.size() ? std::move(parametric)
                                                       : std::vector<double>{};
  em.block(ElementType::Line2).nodes = std::move(segments);
}

class SurfaceSplitter {
 public:
  SurfaceSplitter(const ModelSurface& s, Mesh& mesh, EdgeMiddles& middles)
      : surface_(s), mesh_(mesh), middles_(middles), em_(mesh.entity({2, s.tag})) {}

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
  EntityMesh& em_;
};

}  // namespace

void subdivideIntoQuadrangles(const Model& model, Mesh& mesh) {
  EdgeMiddles middles;
  for (const auto& entry : model.curves()) splitCurve(entry.second, mesh, middles);
  for (const auto& entry : model.surfaces())
    if (mesh.find({2, entry.first})) SurfaceSplitter(entry.second, mesh, middles).run();
}

}  // namespace geomesh
