// ExtrusionMesher: layered sweeps of points and curves, extrusion tops, and what is swept how.
#include "mesh/structured/extrusion_mesher.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <tuple>

#include "mesh/curves/curve_mesher.h"
#include "mesh/core/mesh_error.h"
#include "mesh/structured/swept_volume.h"

namespace geomesh {
namespace {

bool hasLayers(const std::optional<ExtrusionRecord>& record) {
  return record && record->motion && !record->layers.elements.empty();
}

}  // namespace

namespace extrusion {

std::vector<double> layerFractions(const ExtrusionLayers& layers, EntityId id) {
  if (layers.elements.size() != layers.heights.size())
    throw MeshError(id, "Layers has " + std::to_string(layers.elements.size()) +
                            " element counts but " + std::to_string(layers.heights.size()) +
                            " heights");
  std::vector<double> f{0};
  double previous = 0;
  for (std::size_t i = 0; i < layers.elements.size(); ++i) {
    const int n = layers.elements[i];
    const double h = layers.heights[i];
    if (n < 1) throw MeshError(id, "a layer of Layers has fewer than 1 element");
    if (!(h > previous)) throw MeshError(id, "the heights of Layers do not increase from 0");
    for (int j = 1; j <= n; ++j) f.push_back(previous + (h - previous) * j / n);
    previous = h;
  }
  if (std::abs(previous - 1) > 1e-9) throw MeshError(id, "the last height of Layers is not 1");
  f.back() = 1;
  return f;
}

bool isBoundaryLayer(const ExtrusionRecord& record) {
  return record.motion && record.motion->kind == ExtrusionMotion::Kind::Normals;
}

std::vector<double> sweepFractions(const ExtrusionRecord& record, EntityId id) {
  if (!isBoundaryLayer(record) || record.layers.heights.empty())
    return layerFractions(record.layers, id);
  ExtrusionLayers scaled = record.layers;
  const double last = scaled.heights.back();
  if (last == 0 || !std::isfinite(last))
    throw MeshError(id, "the last height of its boundary layer's Layers is zero");
  for (double& h : scaled.heights) h /= last;
  return layerFractions(scaled, id);
}

Vec3 sweptPoint(const Sweep& s, const ExtrusionRecord& record, Vec3 p, double f, EntityId id) {
  if (!isBoundaryLayer(record)) return record.motion->apply(p, f);
  if (!s.normals) throw MeshError(id, "its boundary layer has no normals to grow along");
  return s.normals->moved(s.mesh, record.motion->layerIndex, record.motion->layerView, p,
                          f * record.layers.heights.back(), id);
}

// The nodes of the entity's boundary and of their boundaries, down to points.
static void addClosure(const Model& model, const Mesh& mesh, EntityId e,
                       NodeLocator& locator, std::set<EntityId>& seen) {
  for (int tag : model.boundary(e)) {
    const EntityId b{e.dim - 1, std::abs(tag)};
    if (!seen.insert(b).second) continue;
    if (const EntityMesh* em = mesh.find(b))
      for (NodeIndex n : em->nodes) locator.add(n);
    if (b.dim > 0) addClosure(model, mesh, b, locator, seen);
  }
}

NodeLocator closureLocator(const Model& model, const Mesh& mesh, EntityId e, double tolerance) {
  NodeLocator locator(mesh, tolerance);
  std::set<EntityId> seen;
  addClosure(model, mesh, e, locator, seen);
  return locator;
}

std::string nodeText(NodeIndex n) { return "node " + std::to_string(n + 1); }

}  // namespace extrusion

namespace {

using extrusion::closureLocator;
using extrusion::isBoundaryLayer;
using extrusion::layerFractions;
using extrusion::sweepFractions;
using extrusion::sweptPoint;
using extrusion::nodeText;
using extrusion::NodeLocator;
using extrusion::Sweep;

// The parameter of the curve point nearest to p, by Newton's method from `guess`.
double curveParameter(const CurveGeometry& g, Vec3 p, double guess) {
  const Interval r = g.range();
  double t = std::clamp(guess, r.min, r.max);
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Vec3 d = g.point(t) - p, d1 = g.firstDerivative(t), d2 = g.secondDerivative(t);
    const double slope = dot(d1, d1) + dot(d, d2);
    if (!(slope > 0)) break;
    const double step = dot(d, d1) / slope;
    t = std::clamp(t - step, r.min, r.max);
    if (std::abs(step) <= 1e-15 * (r.max - r.min)) break;
  }
  return t;
}

// Faces of a surface, as flat connectivity.
struct Faces {
  std::vector<NodeIndex> triangles, quadrangles;
};

// The quadrangle a, b, c, d (in order around it), with corners that coincide on a rotation
// axis merged: a triangle, a quadrangle, or both halves of it cut along the diagonal through
// its smallest node.
void addQuadrangle(Faces& faces, std::array<NodeIndex, 4> q, bool recombine) {
  std::vector<NodeIndex> corners;
  for (NodeIndex n : q)
    if (corners.empty() || corners.back() != n) corners.push_back(n);
  if (corners.size() > 1 && corners.front() == corners.back()) corners.pop_back();
  if (corners.size() == 3) {
    faces.triangles.insert(faces.triangles.end(), corners.begin(), corners.end());
  } else if (corners.size() == 4 && recombine) {
    faces.quadrangles.insert(faces.quadrangles.end(), q.begin(), q.end());
  } else if (corners.size() == 4) {
    const auto smallest = std::min_element(q.begin(), q.end()) - q.begin();
    if (smallest % 2 == 0)
      faces.triangles.insert(faces.triangles.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    else
      faces.triangles.insert(faces.triangles.end(), {q[0], q[1], q[3], q[1], q[2], q[3]});
  }
}

Vec3 faceNormal(const Mesh& mesh, std::span<const NodeIndex> f) {
  const Vec3 a = mesh.node(f[0]), b = mesh.node(f[1]), c = mesh.node(f[2]);
  if (f.size() == 3) return cross(b - a, c - a);
  return cross(c - a, mesh.node(f[3]) - b);
}

// Whether a sample of the faces turns, on the whole, like the surface's parametrization
// (du x dv): each face weighs its area, so that the slivers and collapsed faces along a rotation
// axis, where projections are unreliable and du x dv vanishes, cannot outvote the others.
bool agreesWithSurface(const Mesh& mesh, const SurfaceGeometry& g, const Faces& faces) {
  double agreement = 0;
  for (int size : {3, 4}) {
    const std::vector<NodeIndex>& nodes = size == 3 ? faces.triangles : faces.quadrangles;
    const std::size_t count = nodes.size() / static_cast<std::size_t>(size);
    const std::size_t stride = std::max<std::size_t>(1, count / 16);
    for (std::size_t e = 0; e < count; e += stride) {
      const std::span<const NodeIndex> f(nodes.data() + e * size, static_cast<std::size_t>(size));
      Vec3 centre;
      for (NodeIndex n : f) centre = centre + mesh.node(n) / static_cast<double>(size);
      const SurfaceDerivatives d = g.firstDerivatives(g.project(centre));
      const Vec3 normal = cross(d.du, d.dv);
      const double length = norm(normal);
      if (length > 0) agreement += dot(faceNormal(mesh, f), normal) / length;
    }
  }
  return agreement >= 0;
}

// Stores the faces on the surface, turned to agree with its parametrization.
void storeFaces(const Mesh& mesh, const ModelSurface& surface, Faces faces, EntityMesh& em) {
  if (surface.geometry && !agreesWithSurface(mesh, *surface.geometry, faces)) {
    for (std::size_t e = 0; e < faces.triangles.size(); e += 3)
      std::swap(faces.triangles[e + 1], faces.triangles[e + 2]);
    for (std::size_t e = 0; e < faces.quadrangles.size(); e += 4)
      std::swap(faces.quadrangles[e + 1], faces.quadrangles[e + 3]);
  }
  if (!faces.triangles.empty()) em.block(ElementType::Triangle3).nodes = faces.triangles;
  if (!faces.quadrangles.empty()) em.block(ElementType::Quad4).nodes = faces.quadrangles;
}

void addSurfaceNode(Mesh& mesh, const ModelSurface& surface, EntityMesh& em, NodeIndex n) {
  em.nodes.push_back(n);
  if (!surface.geometry) return;
  const Vec2 uv = surface.geometry->project(mesh.node(n));
  em.parametric.insert(em.parametric.end(), {uv.u, uv.v});
}

void meshSweptCurve(const Sweep& s, const ModelCurve& curve, const ExtrusionRecord& record) {
  const EntityId id{1, curve.tag};
  const ModelPoint* source = s.model.point(record.source);
  const bool fromStart = curve.startPoint == record.source;
  if (!source || (!fromStart && curve.endPoint != record.source))
    throw MeshError(id, "its source point " + std::to_string(record.source) + " is not an end");
  const std::vector<double> f = sweepFractions(record, id);
  const NodeIndex sourceNode = pointNode(s.mesh, record.source);
  EntityMesh& em = s.mesh.entity(id);
  std::vector<NodeIndex> chain{sourceNode};
  std::vector<double> parameters;
  const Interval range = curve.geometry ? curve.geometry->range() : Interval{};
  for (std::size_t k = 1; k + 1 < f.size(); ++k) {
    const Vec3 p = sweptPoint(s, record, s.mesh.node(sourceNode), f[k], id);
    chain.push_back(s.mesh.addNode(p));
    s.mesh.setNodeSize(chain.back(), s.mesh.nodeSize(sourceNode));
    const double along = fromStart ? f[k] : 1 - f[k];
    // A boundary layer's curves are shaped by their mesh alone: no parameters on the geometry.
    if (curve.geometry && !isBoundaryLayer(record))
      parameters.push_back(
          curveParameter(*curve.geometry, p, range.min + along * (range.max - range.min)));
  }
  chain.push_back(pointNode(s.mesh, fromStart ? curve.endPoint : curve.startPoint));
  // A boundary layer's point stands where its source does: its node goes to the layer's top.
  if (isBoundaryLayer(record))
    s.mesh.setNode(chain.back(), sweptPoint(s, record, s.mesh.node(sourceNode), 1, id));
  if (!fromStart) {
    std::reverse(chain.begin(), chain.end());
    std::reverse(parameters.begin(), parameters.end());
  }
  em.nodes.assign(chain.begin() + 1, chain.end() - 1);
  em.parametric = std::move(parameters);
  ElementBlock& lines = em.block(ElementType::Line2);
  for (std::size_t k = 1; k < chain.size(); ++k)
    lines.nodes.insert(lines.nodes.end(), {chain[k - 1], chain[k]});
}

// The top curve's mesh is the image of its source's: same number of segments, end points
// matched by position, the order reversed when the copy runs the other way.
void meshImageCurve(const Sweep& s, const ModelCurve& top, const ExtrusionRecord& record) {
  const EntityId id{1, top.tag};
  const std::vector<NodeIndex> chain = curveNodeChain(s.model, s.mesh, record.source);
  NodeLocator ends(s.mesh, s.tolerance);
  ends.add(pointNode(s.mesh, top.startPoint));
  ends.add(pointNode(s.mesh, top.endPoint));
  std::vector<NodeIndex> image;
  std::vector<Vec3> interior;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const Vec3 p = sweptPoint(s, record, s.mesh.node(chain[i]), 1, id);
    if (i > 0 && i + 1 < chain.size()) {
      image.push_back(s.mesh.addNode(p));
      s.mesh.setNodeSize(image.back(), s.mesh.nodeSize(chain[i]));
      continue;
    }
    const std::optional<NodeIndex> end = ends.find(p);
    if (!end)
      throw MeshError(id, "the image of its source curve " + std::to_string(record.source) +
                              " does not end at its end points");
    image.push_back(*end);
  }
  if (image.front() != pointNode(s.mesh, top.startPoint))
    std::reverse(image.begin(), image.end());
  EntityMesh& em = s.mesh.entity(id);
  em.nodes.assign(image.begin() + 1, image.end() - 1);
  if (top.geometry && !isBoundaryLayer(record)) {
    const Interval r = top.geometry->range();
    for (std::size_t i = 1; i + 1 < image.size(); ++i) {
      const double along = static_cast<double>(i) / static_cast<double>(image.size() - 1);
      em.parametric.push_back(curveParameter(*top.geometry, s.mesh.node(image[i]),
                                             r.min + along * (r.max - r.min)));
    }
  }
  ElementBlock& lines = em.block(ElementType::Line2);
  for (std::size_t k = 1; k < image.size(); ++k)
    lines.nodes.insert(lines.nodes.end(), {image[k - 1], image[k]});
}

// The source curve's nodes swept layer by layer; the sweeps of its ends and its last row are
// the boundary's nodes (found by position), the others new nodes of the surface.
void meshSweptSurface(const Sweep& s, const ModelSurface& surface) {
  const EntityId id{2, surface.tag};
  const ExtrusionRecord& record = *surface.extrusion;
  const std::vector<double> f = sweepFractions(record, id);
  const std::vector<NodeIndex> chain = curveNodeChain(s.model, s.mesh, record.source);
  const NodeLocator boundary = closureLocator(s.model, s.mesh, id, s.tolerance);
  EntityMesh& em = s.mesh.entity(id);
  const std::size_t n = chain.size(), layers = f.size() - 1;
  std::vector<NodeIndex> grid(n * (layers + 1));  // (i, k) at k * n + i
  for (std::size_t k = 0; k <= layers; ++k)
    for (std::size_t i = 0; i < n; ++i) {
      if (k == 0) {
        grid[i] = chain[i];
        continue;
      }
      const Vec3 p = sweptPoint(s, record, s.mesh.node(chain[i]), f[k], id);
      if (const std::optional<NodeIndex> found = boundary.find(p)) {
        grid[k * n + i] = *found;
      } else if (k < layers && i > 0 && i + 1 < n) {
        grid[k * n + i] = s.mesh.addNode(p);
        s.mesh.setNodeSize(grid[k * n + i], s.mesh.nodeSize(chain[i]));
        addSurfaceNode(s.mesh, surface, em, grid[k * n + i]);
      } else {
        throw MeshError(id, "the sweep of " + nodeText(chain[i]) +
                                " does not meet the mesh of the surface's boundary");
      }
    }
  Faces faces;
  for (std::size_t k = 0; k < layers; ++k)
    for (std::size_t i = 0; i + 1 < n; ++i)
      addQuadrangle(faces,
                    {grid[k * n + i], grid[k * n + i + 1], grid[(k + 1) * n + i + 1],
                     grid[(k + 1) * n + i]},
                    record.layers.recombine);
  storeFaces(s.mesh, surface, std::move(faces), em);
}

// The top surface's mesh is the image of its source's: same connectivity, the source's
// interior nodes moved, its boundary nodes matched with the top's boundary by position.
void meshImageSurface(const Sweep& s, const ModelSurface& top, const ExtrusionRecord& record) {
  const EntityId id{2, top.tag};
  const EntityMesh* source = s.mesh.find({2, record.source});
  if (!source || source->elementCount() == 0)
    throw MeshError(id, "its source surface " + std::to_string(record.source) + " has no mesh");
  const std::set<NodeIndex> inside(source->nodes.begin(), source->nodes.end());
  const NodeLocator boundary = closureLocator(s.model, s.mesh, id, s.tolerance);
  std::map<NodeIndex, NodeIndex> image;
  Faces faces;
  std::vector<NodeIndex> newNodes;
  for (const ElementBlock& block : source->blocks) {
    if (block.type != ElementType::Triangle3 && block.type != ElementType::Quad4) continue;
    std::vector<NodeIndex>& out =
        block.type == ElementType::Triangle3 ? faces.triangles : faces.quadrangles;
    for (NodeIndex n : block.nodes) {
      auto [it, added] = image.try_emplace(n, 0);
      if (added) {
        const Vec3 p = sweptPoint(s, record, s.mesh.node(n), 1, id);
        if (inside.contains(n)) {
          it->second = s.mesh.addNode(p);
          s.mesh.setNodeSize(it->second, s.mesh.nodeSize(n));
          newNodes.push_back(it->second);
        } else if (const std::optional<NodeIndex> found = boundary.find(p)) {
          it->second = *found;
        } else {
          throw MeshError(id, "the image of " + nodeText(n) + " of its source surface " +
                                  std::to_string(record.source) + " is not on its boundary mesh");
        }
      }
      out.push_back(it->second);
    }
  }
  EntityMesh& em = s.mesh.entity(id);
  for (NodeIndex n : newNodes) addSurfaceNode(s.mesh, top, em, n);
  storeFaces(s.mesh, top, std::move(faces), em);
}

bool isMeshed(const Mesh& mesh, EntityId e) {
  const EntityMesh* em = mesh.find(e);
  return em && em->elementCount() > 0;
}

}  // namespace

bool isLayeredExtrusion(const ModelVolume& volume) { return hasLayers(volume.extrusion); }

ExtrusionMesher::ExtrusionMesher(const Model& model, const post::ViewStore* views)
    : model_(model), normals_(std::make_unique<LayerNormals>(model, views)) {
  const BoundingBox box = model.boundingBox();
  const double diagonal = box.empty() ? 0 : distance(box.min, box.max);
  tolerance_ = 1e-9 * (diagonal > 0 ? diagonal : 1);
  for (const auto& [tag, surface] : model.surfaces())
    if (hasLayers(surface.extrusion) && model.curve(surface.extrusion->top)) {
      topCurves_[surface.extrusion->top] = &*surface.extrusion;
      implySideSweeps(surface);
    }
  for (const auto& [tag, volume] : model.volumes())
    if (hasLayers(volume.extrusion) && model.surface(volume.extrusion->top))
      topSurfaces_[volume.extrusion->top] = &*volume.extrusion;
  for (const auto& [tag, curve] : model.curves())
    if (hasLayers(curve.extrusion) && isBoundaryLayer(*curve.extrusion))
      layerPoints_[curve.startPoint == curve.extrusion->source ? curve.endPoint
                                                               : curve.startPoint] =
          &*curve.extrusion;
}

bool ExtrusionMesher::touchesLayer(EntityId id) const {
  const ModelCurve* curve = id.dim == 1 ? model_.curve(id.tag) : nullptr;
  if (!curve || sweepRecord(id.tag) || imageRecord(id)) return false;
  return layerPoints_.contains(curve->startPoint) || layerPoints_.contains(curve->endPoint);
}

void ExtrusionMesher::followLayerEnds(EntityId id, Mesh& mesh) const {
  const ModelCurve& curve = *model_.curve(id.tag);
  auto moveOf = [&](int point) {
    return mesh.node(pointNode(mesh, point)) - model_.point(point)->xyz;
  };
  const Vec3 start = moveOf(curve.startPoint), end = moveOf(curve.endPoint);
  const std::vector<NodeIndex> chain = curveNodeChain(model_, mesh, id.tag);
  for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(chain.size() - 1);
    mesh.setNode(chain[i], mesh.node(chain[i]) + (1 - t) * start + t * end);
  }
  mesh.entity(id).parametric.clear();  // off the geometry now, as the layer is
}

const ExtrusionRecord* ExtrusionMesher::sweepRecord(int curveTag) const {
  const ModelCurve* curve = model_.curve(curveTag);
  if (curve && hasLayers(curve->extrusion)) return &*curve->extrusion;
  const auto it = impliedSweeps_.find(curveTag);
  return it == impliedSweeps_.end() ? nullptr : &it->second;
}

// A curve bounding a layered sweep of a curve, from an end of the source to an end of the top,
// is the sweep of that end with the same layers, whether or not the kernel says so (the
// OpenCASCADE factory records the sweeps of an extruded surface's curves, not of its corners).
void ExtrusionMesher::implySideSweeps(const ModelSurface& surface) {
  const ExtrusionRecord& record = *surface.extrusion;
  const ModelCurve* source = model_.curve(record.source);
  const ModelCurve* top = model_.curve(record.top);
  if (!source || !top) return;
  auto isEnd = [](const ModelCurve& c, int point) {
    return point == c.startPoint || point == c.endPoint;
  };
  for (int signedTag : model_.boundary({2, surface.tag})) {
    const ModelCurve* side = model_.curve(std::abs(signedTag));
    if (!side || side == source || side == top || side->extrusion ||
        side->startPoint == side->endPoint)
      continue;
    for (const auto& [from, to] : {std::pair{side->startPoint, side->endPoint},
                                  std::pair{side->endPoint, side->startPoint}}) {
      const ModelPoint* a = model_.point(from);
      const ModelPoint* b = model_.point(to);
      if (!a || !b || !isEnd(*source, from) || !isEnd(*top, to) ||
          distance(record.motion->apply(a->xyz, 1), b->xyz) > tolerance_)
        continue;
      impliedSweeps_.try_emplace(side->tag, ExtrusionRecord{from, record.layers, to, record.motion});
      break;
    }
  }
}

bool ExtrusionMesher::sweeps(EntityId id) const {
  if (id.dim == 1) return sweepRecord(id.tag) != nullptr;
  if (id.dim == 2) {
    const ModelSurface* surface = model_.surface(id.tag);
    return surface && hasLayers(surface->extrusion);
  }
  return id.dim == 3 && meshesVolume(id.tag);
}

const ExtrusionRecord* ExtrusionMesher::imageRecord(EntityId id) const {
  if (id.dim != 1 && id.dim != 2) return nullptr;
  const std::map<int, const ExtrusionRecord*>& tops = id.dim == 1 ? topCurves_ : topSurfaces_;
  const auto it = tops.find(id.tag);
  return it == tops.end() ? nullptr : it->second;
}

std::vector<const ExtrusionRecord*> ExtrusionMesher::layerRecords(EntityId id) const {
  std::vector<const ExtrusionRecord*> records;
  auto add = [&](const ExtrusionRecord* record) {
    if (record && isBoundaryLayer(*record)) records.push_back(record);
  };
  if (id.dim == 1) {
    if (touchesLayer(id)) {
      const ModelCurve& curve = *model_.curve(id.tag);
      for (int end : {curve.startPoint, curve.endPoint})
        if (const auto it = layerPoints_.find(end); it != layerPoints_.end()) add(it->second);
    }
    add(sweepRecord(id.tag));
    add(imageRecord(id));
  } else if (const ModelSurface* surface = id.dim == 2 ? model_.surface(id.tag) : nullptr) {
    add(surface->extrusion ? &*surface->extrusion : nullptr);
    add(imageRecord(id));
  }
  return records;
}

bool ExtrusionMesher::waitsForSurfaces(EntityId id) const {
  for (const ExtrusionRecord* record : layerRecords(id))
    if (normals_->fromSurfaces(record->motion->layerIndex)) return true;
  if (id.dim != 2 || !model_.surface(id.tag)) return false;
  for (int c : model_.boundary(id))
    if (waitsForSurfaces({1, std::abs(c)})) return true;
  return false;
}

bool ExtrusionMesher::layerReady(EntityId id, const Mesh& mesh) const {
  for (const ExtrusionRecord* record : layerRecords(id))
    if (!normals_->sourcesMeshed(mesh, record->motion->layerIndex)) return false;
  if (id.dim != 2 || !model_.surface(id.tag)) return true;
  for (int c : model_.boundary(id))
    if (!isMeshed(mesh, {1, std::abs(c)})) return false;
  return true;
}

bool ExtrusionMesher::meshesVolume(int tag) const {
  const ModelVolume* volume = model_.volume(tag);
  return volume && hasLayers(volume->extrusion);
}

void ExtrusionMesher::meshSwept(EntityId id, Mesh& mesh) const {
  const Sweep s{model_, tolerance_, mesh, normals_.get()};
  if (id.dim == 1)
    meshSweptCurve(s, *model_.curve(id.tag), *sweepRecord(id.tag));
  else
    meshSweptSurface(s, *model_.surface(id.tag));
}

void ExtrusionMesher::meshImage(EntityId id, Mesh& mesh) const {
  const ExtrusionRecord* record = imageRecord(id);
  if (!record) throw MeshError(id, "it is the top of no extrusion with layers");
  if (!isMeshed(mesh, {id.dim, record->source}))
    throw MeshError(id, "its source " + std::to_string(record->source) + " has no mesh to copy");
  const Sweep s{model_, tolerance_, mesh, normals_.get()};
  if (id.dim == 1)
    meshImageCurve(s, *model_.curve(id.tag), *record);
  else
    meshImageSurface(s, *model_.surface(id.tag), *record);
}

void ExtrusionMesher::meshVolumes(Mesh& mesh) const {
  const Sweep s{model_, tolerance_, mesh, normals_.get()};
  for (const auto& [tag, volume] : model_.volumes())
    if (hasLayers(volume.extrusion)) extrusion::meshSweptVolume(s, volume);
}

}  // namespace geomesh
