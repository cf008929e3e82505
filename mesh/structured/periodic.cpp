// Periodic curves and surfaces meshed as the affine images of their masters, node for node.
#include "mesh/structured/periodic.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>

#include "mesh/curves/curve_mesher.h"
#include "mesh/core/mesh_error.h"

namespace geomesh {
namespace {

// Two places coincide when closer than this fraction of the model's size.
constexpr double kCoincidence = 1e-8;
// A slave's geometry is the master's image when no node lands farther than this from it.
constexpr double kOnImage = 1e-6;

double modelScale(const Model& model) {
  const BoundingBox box = model.boundingBox();
  const double diagonal = box.empty() ? 0 : distance(box.min, box.max);
  return diagonal > 0 ? diagonal : 1;
}

Vec3 applyLinear(const std::vector<double>& a, Vec3 v) {
  return {a[0] * v.x + a[1] * v.y + a[2] * v.z, a[4] * v.x + a[5] * v.y + a[6] * v.z,
          a[8] * v.x + a[9] * v.y + a[10] * v.z};
}

std::string curveName(int tag) { return "curve " + std::to_string(tag); }
std::string surfaceName(int tag) { return "surface " + std::to_string(tag); }

// The parameter of the point of a curve closest to p, by Newton's method from `guess`.
double projectOnCurve(const CurveGeometry& g, Vec3 p, double guess) {
  const Interval r = g.range();
  double t = guess;
  for (int step = 0; step < 30; ++step) {
    const Vec3 d = g.point(t) - p, d1 = g.firstDerivative(t);
    const double slope = dot(d1, d1) + dot(g.secondDerivative(t), d);
    if (!(slope > 0)) break;
    const double next = std::clamp(t - dot(d1, d) / slope, r.min, r.max);
    const bool converged = std::abs(next - t) <= 1e-15 * (r.max - r.min);
    t = next;
    if (converged) break;
  }
  return t;
}

// How a master curve's mesh lands on its slave: whether the image of the master's start is the
// slave's end.
bool imageIsReversed(const Model& model, const ModelCurve& slave, const ModelCurve& master,
                     const std::vector<double>& affine, double scale) {
  const double tol = kCoincidence * scale;
  const Vec3 a = applyAffine(affine, model.point(master.startPoint)->xyz);
  const Vec3 b = applyAffine(affine, model.point(master.endPoint)->xyz);
  const Vec3 s = model.point(slave.startPoint)->xyz, e = model.point(slave.endPoint)->xyz;
  const bool forward = distance(a, s) <= tol && distance(b, e) <= tol;
  const bool backward = distance(a, e) <= tol && distance(b, s) <= tol;
  if (forward && backward) {  // closed curves: compare the directions at the start
    const Vec3 image = applyLinear(affine, master.geometry->firstDerivative(
                                               master.geometry->range().min));
    return dot(image, slave.geometry->firstDerivative(slave.geometry->range().min)) < 0;
  }
  if (forward || backward) return backward;
  throw MeshError({1, slave.tag}, "the transformation of its periodicity does not map the end "
                                  "points of its master " + curveName(master.tag) +
                                      " onto its own");
}

void copyCurve(const Model& model, const ModelCurve& slave, const Periodicity& link, double scale,
               Mesh& mesh) {
  const EntityId id{1, slave.tag};
  const ModelCurve* master = model.curve(link.master);
  if (!master || !master->geometry || !slave.geometry)
    throw MeshError(id, "its periodic master " + curveName(link.master) + " has no geometry");
  const bool reversed = imageIsReversed(model, slave, *master, link.affine, scale);
  std::vector<NodeIndex> masterChain = curveNodeChain(model, mesh, master->tag);
  std::vector<double> masterParams = mesh.find({1, master->tag})->parametric;
  if (reversed) {
    std::reverse(masterChain.begin(), masterChain.end());
    std::reverse(masterParams.begin(), masterParams.end());
  }
  const CurveGeometry& g = *slave.geometry;
  const Interval ms = master->geometry->range(), ss = g.range();
  const double tol = kOnImage * scale;

  EntityMesh& em = mesh.entity(id);
  em.nodes.clear();
  em.parametric.clear();
  em.blocks.clear();
  std::vector<NodeIndex> chain{pointNode(mesh, slave.startPoint)};
  const NodeIndex slaveEnd = pointNode(mesh, slave.endPoint);
  PeriodicLink out{link.master, link.affine, {{chain.front(), masterChain.front()}}};
  if (slave.endPoint != slave.startPoint) out.nodes.push_back({slaveEnd, masterChain.back()});
  for (std::size_t k = 1; k + 1 < masterChain.size(); ++k) {
    const NodeIndex from = masterChain[k];
    const Vec3 image = applyAffine(link.affine, mesh.node(from));
    double fraction = static_cast<double>(k) / static_cast<double>(masterChain.size() - 1);
    if (masterParams.size() + 2 == masterChain.size())
      fraction = std::abs(masterParams[k - 1] - (reversed ? ms.max : ms.min)) / (ms.max - ms.min);
    const double t = projectOnCurve(g, image, ss.min + fraction * (ss.max - ss.min));
    const Vec3 onCurve = g.point(t);
    if (distance(onCurve, image) > tol)
      throw MeshError(id, "it is not the image of its periodic master " + curveName(master->tag));
    const NodeIndex node = mesh.addNode(onCurve);
    mesh.setNodeSize(node, mesh.nodeSize(from));
    em.nodes.push_back(node);
    em.parametric.push_back(t);
    chain.push_back(node);
    out.nodes.push_back({node, from});
  }
  chain.push_back(slaveEnd);
  ElementBlock& lines = em.block(ElementType::Line2);
  for (std::size_t k = 0; k + 1 < chain.size(); ++k)
    lines.nodes.insert(lines.nodes.end(), {chain[k], chain[k + 1]});
  em.periodic = std::move(out);
}

// The end point of curve c whose node is `node`, or 0.
int endPointOfNode(const Mesh& mesh, NodeIndex node, const ModelCurve& c) {
  for (int tag : {c.startPoint, c.endPoint})
    if (pointNode(mesh, tag) == node) return tag;
  return 0;
}

// Each end point of a periodic curve is the image of its master's matching end point.
void linkEndPoints(const Model& model, const std::map<int, Periodicity>& links, Mesh& mesh) {
  for (const auto& entry : links) {
    const ModelCurve* master = model.curve(entry.second.master);
    const EntityMesh* em = mesh.find({1, entry.first});
    if (!master || !em || !em->periodic) continue;
    // The end points' pairs come first (one for a closed curve).
    const auto& pairs = em->periodic->nodes;
    const ModelCurve& slave = *model.curve(entry.first);
    for (std::size_t k = 0; k < std::min<std::size_t>(pairs.size(), 2); ++k) {
      const auto [slaveNode, masterNode] = pairs[k];
      const int slavePoint = endPointOfNode(mesh, slaveNode, slave);
      const int masterPoint = endPointOfNode(mesh, masterNode, *master);
      if (slavePoint == 0 || masterPoint == 0 || slavePoint == masterPoint) continue;
      EntityMesh& point = mesh.entity({0, slavePoint});
      if (point.periodic) continue;
      point.periodic = PeriodicLink{masterPoint, entry.second.affine, {{slaveNode, masterNode}}};
    }
  }
}

// The slave's boundary curve the image of `curve` coincides with, or 0.
int imageCurve(const Model& model, const ModelCurve& curve, const std::vector<double>& affine,
               const std::vector<int>& candidates, double scale) {
  const double tol = kCoincidence * scale;
  const Interval r = curve.geometry->range();
  const Vec3 a = applyAffine(affine, model.point(curve.startPoint)->xyz);
  const Vec3 b = applyAffine(affine, model.point(curve.endPoint)->xyz);
  const Vec3 mid = applyAffine(affine, curve.geometry->point(0.5 * (r.min + r.max)));
  for (int tag : candidates) {
    const ModelCurve* c = model.curve(tag);
    if (!c || !c->geometry) continue;
    const Vec3 s = model.point(c->startPoint)->xyz, e = model.point(c->endPoint)->xyz;
    const bool ends = (distance(a, s) <= tol && distance(b, e) <= tol) ||
                      (distance(a, e) <= tol && distance(b, s) <= tol);
    const Interval cr = c->geometry->range();
    const double t = projectOnCurve(*c->geometry, mid, 0.5 * (cr.min + cr.max));
    if (ends && distance(c->geometry->point(t), mid) <= kOnImage * scale) return tag;
  }
  return 0;
}

std::vector<int> boundaryCurves(const Model& model, int surface) {
  std::vector<int> tags;
  for (int signedTag : model.boundary({2, surface})) tags.push_back(std::abs(signedTag));
  return tags;
}

// Nodes found by position: a hash grid of cells twice the tolerance wide, so that a query
// looks at its cell and the 26 around it.
class NodeLocator {
 public:
  NodeLocator(const Mesh& mesh, const std::vector<NodeIndex>& nodes, double tol)
      : mesh_(mesh), tol_(tol), cell_(2 * tol) {
    for (NodeIndex n : nodes) cells_.emplace(key(cellOf(mesh.node(n))), n);
  }
  // The node at p, or nullopt.
  std::optional<NodeIndex> at(Vec3 p) const {
    const std::array<std::int64_t, 3> c = cellOf(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto [first, last] = cells_.equal_range(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          for (auto it = first; it != last; ++it)
            if (distance(mesh_.node(it->second), p) <= tol_) return it->second;
        }
    return std::nullopt;
  }

 private:
  std::array<std::int64_t, 3> cellOf(Vec3 p) const {
    return {static_cast<std::int64_t>(std::floor(p.x / cell_)),
            static_cast<std::int64_t>(std::floor(p.y / cell_)),
            static_cast<std::int64_t>(std::floor(p.z / cell_))};
  }
  static std::uint64_t key(std::array<std::int64_t, 3> c) {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
    return h;
  }

  const Mesh& mesh_;
  double tol_, cell_;
  std::unordered_multimap<std::uint64_t, NodeIndex> cells_;
};

std::vector<NodeIndex> closureBoundaryNodes(const Model& model, const Mesh& mesh, int surface) {
  std::vector<NodeIndex> nodes;
  for (int curve : boundaryCurves(model, surface)) {
    const std::vector<NodeIndex> chain = curveNodeChain(model, mesh, curve);
    nodes.insert(nodes.end(), chain.begin(), chain.end());
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// Reverses every element of the surface's mesh when the first one's normal opposes the
// surface's: the image of a positively oriented mesh is consistently oriented, one way or the
// other.
void orientAlongNormal(const SurfaceGeometry& g, const Mesh& mesh, EntityMesh& em) {
  for (ElementBlock& block : em.blocks) {
    if (block.size() == 0) continue;
    const auto e = block.element(0);
    const Vec3 a = mesh.node(e[0]), b = mesh.node(e[1]), c = mesh.node(e[2]);
    const SurfaceDerivatives d = g.firstDerivatives(g.project((a + b + c) / 3));
    if (dot(cross(b - a, c - a), cross(d.du, d.dv)) >= 0) continue;
    const std::size_t n = nodeCount(block.type);
    for (std::size_t k = 0; k < block.size(); ++k)
      std::reverse(block.nodes.begin() + k * n + 1, block.nodes.begin() + (k + 1) * n);
  }
}

void copySurface(const Model& model, const ModelSurface& slave, double scale, Mesh& mesh) {
  const EntityId id{2, slave.tag};
  const Periodicity& link = *slave.periodic;
  const EntityMesh* masterMesh = mesh.find({2, link.master});
  if (!model.surface(link.master) || !masterMesh)
    throw MeshError(id, "its periodic master " + surfaceName(link.master) + " has no mesh");
  std::unordered_map<NodeIndex, NodeIndex> image;  // master node -> slave node
  const NodeLocator slaveBoundary(mesh, closureBoundaryNodes(model, mesh, slave.tag),
                                  kCoincidence * scale);
  PeriodicLink out{link.master, link.affine, {}};
  for (NodeIndex from : closureBoundaryNodes(model, mesh, link.master)) {
    const std::optional<NodeIndex> to = slaveBoundary.at(applyAffine(link.affine, mesh.node(from)));
    if (!to)
      throw MeshError(id, "its boundary nodes are not the images of those of its periodic "
                          "master " + surfaceName(link.master));
    image.emplace(from, *to);
    out.nodes.push_back({*to, from});
  }
  EntityMesh& em = mesh.entity(id);  // entities live in a map: masterMesh stays valid
  em.nodes.clear();
  em.parametric.clear();
  em.blocks.clear();
  for (const ElementBlock& from : masterMesh->blocks) {
    ElementBlock& to = em.block(from.type);
    for (NodeIndex n : from.nodes) {
      auto [it, added] = image.try_emplace(n, 0);
      if (added) {
        const Vec3 p = applyAffine(link.affine, mesh.node(n));
        Vec3 q = p;
        if (slave.geometry) {
          const Vec2 uv = slave.geometry->project(p);
          q = slave.geometry->point(uv);
          em.parametric.insert(em.parametric.end(), {uv.u, uv.v});
        }
        if (distance(p, q) > kOnImage * scale)
          throw MeshError(id, "it is not the image of its periodic master " +
                                  surfaceName(link.master));
        it->second = mesh.addNode(q);
        mesh.setNodeSize(it->second, mesh.nodeSize(n));
        em.nodes.push_back(it->second);
        out.nodes.push_back({it->second, n});
      }
      to.nodes.push_back(it->second);
    }
  }
  if (slave.geometry) orientAlongNormal(*slave.geometry, mesh, em);
  em.periodic = std::move(out);
}

}  // namespace

Vec3 applyAffine(const std::vector<double>& a, Vec3 p) {
  if (a.size() < 12) return p;
  return applyLinear(a, p) + Vec3{a[3], a[7], a[11]};
}

std::map<int, Periodicity> periodicCurves(const Model& model) {
  std::map<int, Periodicity> links;
  const double scale = modelScale(model);
  for (const auto& [tag, curve] : model.curves())
    if (curve.periodic) links[tag] = *curve.periodic;
  for (const auto& [tag, surface] : model.surfaces()) {
    if (!surface.periodic) continue;
    const std::vector<int> slaveCurves = boundaryCurves(model, tag);
    for (int masterCurve : boundaryCurves(model, surface.periodic->master)) {
      const ModelCurve* c = model.curve(masterCurve);
      if (!c || !c->geometry) continue;
      const int slaveCurve = imageCurve(model, *c, surface.periodic->affine, slaveCurves, scale);
      if (slaveCurve == 0)
        throw MeshError({2, tag}, "the image of " + curveName(masterCurve) +
                                      " of its periodic master " +
                                      surfaceName(surface.periodic->master) +
                                      " is none of its boundary curves");
      // A curve already declared periodic keeps its link; so does one whose master the
      // script made its copy (Periodic Curve{1} = {-3}; then surfaces the other way round):
      // either way the two curves get matching meshes.
      const auto reverse = links.find(masterCurve);
      const bool reversed = reverse != links.end() && reverse->second.master == slaveCurve;
      if (slaveCurve != masterCurve && !links.contains(slaveCurve) && !reversed)
        links[slaveCurve] = {masterCurve, surface.periodic->affine};
    }
  }
  return links;
}

PeriodicCopier::PeriodicCopier(const Model& model) : model_(model), scale_(modelScale(model)) {}

void PeriodicCopier::copyCurve(int tag, const Periodicity& link, Mesh& mesh) const {
  const EntityMesh* master = mesh.find({1, link.master});
  if (!master || master->elementCount() == 0)
    throw MeshError({1, tag}, "its periodic master " + curveName(link.master) + " has no mesh");
  geomesh::copyCurve(model_, *model_.curve(tag), link, scale_, mesh);
}

void PeriodicCopier::linkEndPoints(const std::map<int, Periodicity>& links, Mesh& mesh) const {
  geomesh::linkEndPoints(model_, links, mesh);
}

void PeriodicCopier::copySurface(int tag, Mesh& mesh) const {
  geomesh::copySurface(model_, *model_.surface(tag), scale_, mesh);
}

}  // namespace geomesh
