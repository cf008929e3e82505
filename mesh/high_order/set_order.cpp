// setOrder: new nodes on edges, faces and insides of elements, shared through their lattice
// weights on the sub-entity's vertices, placed on the curve or surface they belong to.
#include "mesh/high_order/set_order.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "mesh/core/mesh_error.h"
#include "mesh/high_order/curved_repair.h"
#include "mesh/high_order/reference_element.h"
#include "mesh/high_order/shape_functions.h"

namespace geomesh {
namespace {

// A node on an edge or a face, named by the vertices of that edge or face (sorted) and its
// weights on them: the same for every element that shares the edge or face.
struct SharedKey {
  std::array<NodeIndex, 4> vertices{};
  std::array<std::uint16_t, 4> weights{};
  std::uint16_t count = 0;
  friend bool operator==(const SharedKey&, const SharedKey&) = default;
};

struct SharedKeyHash {
  std::size_t operator()(const SharedKey& k) const {
    std::size_t h = k.count;
    for (int i = 0; i < k.count; ++i)
      h = h * 1000003u ^ (std::size_t{k.vertices[i]} * 31u + k.weights[i]);
    return h;
  }
};

SharedKey keyOf(const NodePlace& place, std::span<const NodeIndex> corners) {
  std::array<std::pair<NodeIndex, std::uint16_t>, 4> pairs{};
  for (int c = 0; c < place.cornerCount; ++c)
    pairs[c] = {corners[place.corners[c]], place.weights[c]};
  std::sort(pairs.begin(), pairs.begin() + place.cornerCount);
  SharedKey key;
  key.count = place.cornerCount;
  for (int c = 0; c < place.cornerCount; ++c)
    key.vertices[c] = pairs[c].first, key.weights[c] = pairs[c].second;
  return key;
}

// The entity an element block lies on, with what placing nodes on it needs.
// The corners of the element being raised: their nodes and where they are.
struct Corners {
  std::span<const NodeIndex> nodes;
  std::array<Vec3, 8> xyz{};
  std::span<const Vec3> points() const { return {xyz.data(), nodes.size()}; }
};

struct Support {
  EntityId id;
  const CurveGeometry* curve = nullptr;
  const SurfaceGeometry* surface = nullptr;
  std::unordered_map<NodeIndex, double> curveParameter;  // corners' parameters on the curve
  std::unordered_map<NodeIndex, Vec2> surfaceParameter;  // nodes classified on the surface
};

class Elevator {
 public:
  Elevator(const Model& model, const MeshOptions& options, Mesh& mesh)
      : model_(model), options_(options), mesh_(mesh) {}

  std::size_t nodesAdded() const { return added_; }

  void elevate(EntityMesh& em) {
    const Support support = supportOf(em);
    bool onGeometry = true;
    for (ElementBlock& block : em.blocks) {
      const ElementFamily f = family(block.type);
      if (f == ElementFamily::Point) continue;
      if (f == ElementFamily::Prism && options_.elementOrder > 2)
        throw MeshError(em.entity, "prisms of order " + std::to_string(options_.elementOrder) +
                                       " are not supported (prisms go up to order 2)");
      const ElementType to = *elementTypeOf(f, options_.elementOrder,
                                            options_.secondOrderIncomplete);
      const ReferenceElement& ref = referenceElement(to);
      const std::size_t corners = vertexCount(f), elements = block.size();
      std::vector<NodeIndex> nodes;
      nodes.reserve(elements * ref.xi.size());
      for (std::size_t e = 0; e < elements; ++e) {
        Corners c{block.element(e).first(corners)};
        for (std::size_t v = 0; v < corners; ++v) c.xyz[v] = mesh_.node(c.nodes[v]);
        const std::size_t first = nodes.size();
        for (std::size_t k = 0; k < ref.places.size(); ++k) {
          const std::span<const NodeIndex> made(nodes.data() + first, k);
          nodes.push_back(nodeAt(ref, k, c, made, support, em, onGeometry));
        }
      }
      block.type = to;
      block.nodes = std::move(nodes);
    }
    if (!onGeometry) em.parametric.clear();
  }

 private:
  Support supportOf(const EntityMesh& em) const {
    Support s;
    s.id = em.entity;
    if (options_.secondOrderLinear) return s;
    if (em.entity.dim == 1) {
      const ModelCurve* curve = model_.curve(em.entity.tag);
      if (!curve || !curve->geometry || curve->geometry->isDegenerate()) return s;
      if (em.parametric.size() != em.nodes.size()) return s;
      s.curve = curve->geometry.get();
      for (std::size_t k = 0; k < em.nodes.size(); ++k)
        s.curveParameter[em.nodes[k]] = em.parametric[k];
    } else if (em.entity.dim == 2) {
      const ModelSurface* surface = model_.surface(em.entity.tag);
      if (!surface || !surface->geometry || surface->geometry->isPlane()) return s;
      s.surface = surface->geometry.get();
      if (em.parametric.size() == 2 * em.nodes.size())
        for (std::size_t k = 0; k < em.nodes.size(); ++k)
          s.surfaceParameter[em.nodes[k]] = {em.parametric[2 * k], em.parametric[2 * k + 1]};
    }
    return s;
  }

  // Node k of an element whose nodes before k are `made`.
  NodeIndex nodeAt(const ReferenceElement& ref, std::size_t k, const Corners& corners,
                   std::span<const NodeIndex> made, const Support& support, EntityMesh& em,
                   bool& onGeometry) {
    const NodePlace& place = ref.places[k];
    if (place.kind == NodePlace::Vertex) return corners.nodes[place.corners[0]];
    if (place.kind == NodePlace::Cell)
      return addNode(em, blended(ref, k, corners, made), {}, onGeometry);
    const SharedKey key = keyOf(place, corners.nodes);
    if (auto it = shared_.find(key); it != shared_.end()) return it->second;
    const Vec3 guess = place.kind == NodePlace::Face
                           ? blended(ref, k, corners, made)
                           : linearImage(ref.family, ref.xi[k], corners.points());
    const NodeIndex node = placeOn(support, place, corners.nodes, guess, em, onGeometry);
    shared_.emplace(key, node);
    return node;
  }

  // Where a face or inside node goes when the element's edges are curved: its straight
  // position moved by the edges' displacements, interpolated by the shape functions of the
  // serendipity element (vertex and edge nodes only) of the same order.
  Vec3 blended(const ReferenceElement& ref, std::size_t k, const Corners& corners,
               std::span<const NodeIndex> made) const {
    const Vec3 straight = linearImage(ref.family, ref.xi[k], corners.points());
    if (options_.secondOrderLinear) return straight;
    const std::optional<ElementType> edgesOnly = elementTypeOf(ref.family, ref.order, true);
    if (!edgesOnly || !isSerendipity(*edgesOnly) || nodeCount(*edgesOnly) > int(made.size()))
      return straight;
    const ShapeFunctions& shape = shapeFunctions(*edgesOnly);
    std::vector<double> n(shape.size());
    shape.values(ref.xi[k], n);
    Vec3 shift{0, 0, 0};
    for (int j = vertexCount(ref.family); j < shape.size(); ++j)
      shift += n[j] * (mesh_.node(made[j]) - linearImage(ref.family, ref.xi[j], corners.points()));
    return straight + shift;
  }

  // A node on an edge or a face, near `straight` (its straight or blended position).
  NodeIndex placeOn(const Support& s, const NodePlace& place, std::span<const NodeIndex> corners,
                    Vec3 straight, EntityMesh& em, bool& onGeometry) {
    if (s.curve) {
      if (const std::optional<double> t = curveParameter(s, place, corners))
        return addNode(em, s.curve->point(*t), std::array{*t}, onGeometry);
    } else if (s.surface) {
      const Vec2 uv = surfaceParameter(s, place, corners, straight);
      return addNode(em, s.surface->point(uv), std::array{uv.u, uv.v}, onGeometry);
    } else if (em.entity.dim == 2 && em.parametric.size() == 2 * em.nodes.size()) {
      const ModelSurface* plane = model_.surface(em.entity.tag);
      if (plane && plane->geometry && !options_.secondOrderLinear) {
        const Vec2 uv = plane->geometry->project(straight);
        return addNode(em, straight, std::array{uv.u, uv.v}, onGeometry);
      }
    }
    return addNode(em, straight, {}, onGeometry);
  }

  // The parameter of a corner on the curve: its own, or the end of the range it sits at.
  std::optional<double> cornerParameter(const Support& s, NodeIndex node,
                                        std::optional<double> near) const {
    if (auto it = s.curveParameter.find(node); it != s.curveParameter.end()) return it->second;
    const ModelCurve& curve = *model_.curve(s.id.tag);
    const Interval range = s.curve->range();
    const bool atStart = isPointNode(curve.startPoint, node), atEnd = isPointNode(curve.endPoint, node);
    if (atStart && atEnd)  // a closed curve: the end nearer the other corner
      return near && *near > (range.min + range.max) / 2 ? range.max : range.min;
    if (atStart) return range.min;
    if (atEnd) return range.max;
    return std::nullopt;
  }

  std::optional<double> curveParameter(const Support& s, const NodePlace& place,
                                       std::span<const NodeIndex> corners) const {
    const NodeIndex a = corners[place.corners[0]], b = corners[place.corners[1]];
    const auto known = [&](NodeIndex n) -> std::optional<double> {
      auto it = s.curveParameter.find(n);
      return it == s.curveParameter.end() ? std::nullopt : std::optional<double>(it->second);
    };
    const std::optional<double> ta = cornerParameter(s, a, known(b));
    const std::optional<double> tb = cornerParameter(s, b, ta ? ta : known(a));
    if (!ta || !tb) return std::nullopt;
    return (*ta * place.weights[0] + *tb * place.weights[1]) / place.total;
  }

  bool isPointNode(int pointTag, NodeIndex node) const {
    const EntityMesh* pm = mesh_.find({0, pointTag});
    return pm && !pm->nodes.empty() && pm->nodes.front() == node;
  }

  // Interpolated from the corners' parameters when they are all known, else the straight
  // position projected.
  Vec2 surfaceParameter(const Support& s, const NodePlace& place,
                        std::span<const NodeIndex> corners, Vec3 straight) const {
    Vec2 uv{0, 0};
    double size = 0;
    bool known = true;
    for (int c = 0; c < place.cornerCount && known; ++c) {
      const NodeIndex n = corners[place.corners[c]];
      auto it = s.surfaceParameter.find(n);
      if (it == s.surfaceParameter.end()) known = false;
      else {
        const double w = double(place.weights[c]) / place.total;
        uv = {uv.u + w * it->second.u, uv.v + w * it->second.v};
        size = std::max(size, distance(mesh_.node(n), straight));
      }
    }
    // A node off the straight position by more than a small fraction of the element size is
    // suspect (a pole or a seam between the corners); the closest surface point is then taken.
    if (!known) return s.surface->project(straight);
    const double off = distance(s.surface->point(uv), straight);
    if (off <= 0.05 * size) return uv;
    const Vec2 projected = s.surface->project(straight);
    return distance(s.surface->point(projected), straight) < off ? projected : uv;
  }

  // A new node on em; `parameters` are its own on em's curve or surface, empty if unknown.
  NodeIndex addNode(EntityMesh& em, Vec3 x, std::span<const double> parameters,
                    bool& onGeometry) {
    const NodeIndex node = mesh_.addNode(x);
    ++added_;
    const std::size_t stride = em.entity.dim == 1 ? 1 : 2;
    const bool complete = (em.entity.dim == 1 || em.entity.dim == 2) &&
                          em.parametric.size() == stride * em.nodes.size();
    em.nodes.push_back(node);
    if (complete && parameters.size() == stride)
      em.parametric.insert(em.parametric.end(), parameters.begin(), parameters.end());
    else if (complete)
      onGeometry = false;
    return node;
  }

  const Model& model_;
  const MeshOptions& options_;
  Mesh& mesh_;
  std::unordered_map<SharedKey, NodeIndex, SharedKeyHash> shared_;
  std::size_t added_ = 0;
};

// Every entity the mesh has, by dimension first: a list to walk while the meshes change.
std::vector<EntityId> meshedEntities(const Mesh& mesh) {
  std::vector<EntityId> ids;
  for (const auto& entry : mesh.entities()) ids.push_back(entry.first);
  return ids;
}

// Drops every node that is not a vertex of an element, and makes every block first order.
void reduceToFirstOrder(Mesh& mesh) {
  std::unordered_set<NodeIndex> vertices;
  bool any = false;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks) {
      any = any || order(b.type) > 1;
      const std::size_t v = vertexCount(b.type);
      for (std::size_t e = 0; e < b.size(); ++e)
        for (NodeIndex n : b.element(e).first(v)) vertices.insert(n);
    }
  if (!any) return;
  for (const EntityId id : meshedEntities(mesh)) {
    EntityMesh& em = mesh.entity(id);
    for (ElementBlock& b : em.blocks) {
      const std::size_t v = vertexCount(b.type), n = nodeCount(b.type);
      std::vector<NodeIndex> kept;
      kept.reserve(b.size() * v);
      for (std::size_t e = 0; e < b.size(); ++e)
        for (std::size_t k = 0; k < v; ++k) kept.push_back(b.nodes[e * n + k]);
      b.type = linearType(family(b.type));
      b.nodes = std::move(kept);
    }
    const std::size_t stride = id.dim == 1 ? 1 : 2;
    const bool withParameters = id.dim >= 1 && id.dim <= 2 && !em.nodes.empty() &&
                                em.parametric.size() == stride * em.nodes.size();
    std::vector<NodeIndex> nodes;
    std::vector<double> parametric;
    for (std::size_t k = 0; k < em.nodes.size(); ++k) {
      if (id.dim > 0 && !vertices.contains(em.nodes[k])) continue;
      nodes.push_back(em.nodes[k]);
      if (withParameters)
        parametric.insert(parametric.end(), em.parametric.begin() + stride * k,
                          em.parametric.begin() + stride * (k + 1));
    }
    em.nodes = std::move(nodes);
    if (withParameters) em.parametric = std::move(parametric);
  }
  mesh.dropUnheldNodes();
}

}  // namespace

std::string unsupportedOrderReason(int order) {
  if (order >= 1 && order <= kMaxElementOrder) return "";
  return "element order " + std::to_string(order) + " is not supported (1 to " +
         std::to_string(kMaxElementOrder) + ")";
}

HighOrderSummary setOrder(const Model& model, const MeshOptions& options, Mesh& mesh,
                          MessageSink& log) {
  HighOrderSummary summary;
  if (const std::string why = unsupportedOrderReason(options.elementOrder); !why.empty())
    throw std::invalid_argument(why);
  reduceToFirstOrder(mesh);
  if (options.elementOrder == 1) return summary;
  Elevator elevator(model, options, mesh);
  for (const EntityId id : meshedEntities(mesh)) elevator.elevate(mesh.entity(id));
  summary.nodesAdded = elevator.nodesAdded();
  if (!options.secondOrderLinear) repairCurvedElements(model, options, mesh, log, summary);
  return summary;
}

}  // namespace geomesh
