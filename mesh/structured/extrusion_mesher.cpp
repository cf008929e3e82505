// ExtrusionMesher: layered sweeps into segments, quads or triangles, prisms, hexahedra, tets.
#include "mesh/structured/extrusion_mesher.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <tuple>

#include "mesh/curves/curve_mesher.h"
#include "mesh/core/mesh_error.h"

namespace geomesh {
namespace {

bool hasLayers(const std::optional<ExtrusionRecord>& record) {
  return record && record->motion && !record->layers.elements.empty();
}

// The normalized heights of the layer boundaries, from 0 to 1: layer i adds elements[i] equal
// steps up to heights[i].
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

// Finds existing nodes by position, within a tolerance, through a hash grid.
class NodeLocator {
 public:
  NodeLocator(const Mesh& mesh, double tolerance)
      : mesh_(mesh), tolerance_(tolerance), cell_(4 * tolerance) {}

  void add(NodeIndex n) { cells_[key(mesh_.node(n))].push_back(n); }

  std::optional<NodeIndex> find(Vec3 p) const {
    const auto [x, y, z] = key(p);
    for (long long i = x - 1; i <= x + 1; ++i)
      for (long long j = y - 1; j <= y + 1; ++j)
        for (long long k = z - 1; k <= z + 1; ++k)
          if (const auto it = cells_.find({i, j, k}); it != cells_.end())
            for (NodeIndex n : it->second)
              if (distance(mesh_.node(n), p) <= tolerance_) return n;
    return std::nullopt;
  }

 private:
  using Key = std::tuple<long long, long long, long long>;
  Key key(Vec3 p) const {
    return {std::llround(p.x / cell_), std::llround(p.y / cell_), std::llround(p.z / cell_)};
  }

  const Mesh& mesh_;
  double tolerance_, cell_;
  std::map<Key, std::vector<NodeIndex>> cells_;
};

// The nodes of the entity's boundary and of their boundaries, down to points.
void addClosure(const Model& model, const Mesh& mesh, EntityId e, NodeLocator& locator,
                std::set<EntityId>& seen) {
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

double signedVolume(const Mesh& mesh, NodeIndex a, NodeIndex b, NodeIndex c, NodeIndex d) {
  const Vec3 pa = mesh.node(a);
  return dot(cross(mesh.node(b) - pa, mesh.node(c) - pa), mesh.node(d) - pa);
}

// The three tetrahedra of the prism a, b, c (bottom) and d, e, f (top, d above a): every
// quadrangular face is cut along the diagonal through its smallest node. Tetrahedra that
// collapse (a vertical edge on a rotation axis) are left out; the others are turned positive.
void splitPrism(const Mesh& mesh, std::array<NodeIndex, 6> v, std::vector<NodeIndex>& tets) {
  auto m = std::min_element(v.begin(), v.end()) - v.begin();
  if (m >= 3) {
    std::swap_ranges(v.begin(), v.begin() + 3, v.begin() + 3);
    m -= 3;
  }
  std::rotate(v.begin(), v.begin() + m, v.begin() + 3);
  std::rotate(v.begin() + 3, v.begin() + 3 + m, v.end());
  const auto [a, b, c, d, e, f] = v;
  std::array<std::array<NodeIndex, 4>, 3> split;
  if (std::min(b, f) < std::min(c, e))
    split = {{{a, b, c, f}, {a, b, f, e}, {a, e, f, d}}};
  else
    split = {{{a, b, c, e}, {a, e, c, f}, {a, e, f, d}}};
  for (auto t : split) {
    std::array<NodeIndex, 4> sorted = t;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) continue;
    if (signedVolume(mesh, t[0], t[1], t[2], t[3]) < 0) std::swap(t[1], t[2]);
    tets.insert(tets.end(), t.begin(), t.end());
  }
}

// What every sweep reads.
struct Sweep {
  const Model& model;
  double tolerance;
  Mesh& mesh;
};

void meshSweptCurve(const Sweep& s, const ModelCurve& curve, const ExtrusionRecord& record) {
  const EntityId id{1, curve.tag};
  const ModelPoint* source = s.model.point(record.source);
  const bool fromStart = curve.startPoint == record.source;
  if (!source || (!fromStart && curve.endPoint != record.source))
    throw MeshError(id, "its source point " + std::to_string(record.source) + " is not an end");
  const std::vector<double> f = layerFractions(record.layers, id);
  const NodeIndex sourceNode = pointNode(s.mesh, record.source);
  EntityMesh& em = s.mesh.entity(id);
  std::vector<NodeIndex> chain{sourceNode};
  std::vector<double> parameters;
  const Interval range = curve.geometry ? curve.geometry->range() : Interval{};
  for (std::size_t k = 1; k + 1 < f.size(); ++k) {
    const Vec3 p = record.motion->apply(source->xyz, f[k]);
    chain.push_back(s.mesh.addNode(p));
    s.mesh.setNodeSize(chain.back(), s.mesh.nodeSize(sourceNode));
    const double along = fromStart ? f[k] : 1 - f[k];
    if (curve.geometry)
      parameters.push_back(
          curveParameter(*curve.geometry, p, range.min + along * (range.max - range.min)));
  }
  chain.push_back(pointNode(s.mesh, fromStart ? curve.endPoint : curve.startPoint));
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
    const Vec3 p = record.motion->apply(s.mesh.node(chain[i]), 1);
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
  if (top.geometry) {
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
  const std::vector<double> f = layerFractions(record.layers, id);
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
      const Vec3 p = record.motion->apply(s.mesh.node(chain[i]), f[k]);
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
        const Vec3 p = record.motion->apply(s.mesh.node(n), 1);
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

// The nodes of each source node's sweep, layer by layer: the boundary's nodes where the sweep
// meets it (found by position), new nodes of the volume elsewhere.
class Columns {
 public:
  Columns(const Sweep& s, const ModelVolume& volume, const EntityMesh& source,
          std::vector<double> fractions)
      : s_(s),
        volume_(volume),
        motion_(*volume.extrusion->motion),
        inside_(source.nodes.begin(), source.nodes.end()),
        boundary_(closureLocator(s.model, s.mesh, {3, volume.tag}, s.tolerance)),
        f_(std::move(fractions)) {}

  const std::vector<NodeIndex>& of(NodeIndex n) {
    auto [it, added] = columns_.try_emplace(n);
    if (!added) return it->second;
    std::vector<NodeIndex>& column = it->second;
    column.push_back(n);
    for (std::size_t k = 1; k < f_.size(); ++k) {
      const Vec3 p = motion_.apply(s_.mesh.node(n), f_[k]);
      if (const std::optional<NodeIndex> found = boundary_.find(p)) {
        column.push_back(*found);
      } else if (inside_.contains(n) && k + 1 < f_.size()) {
        column.push_back(s_.mesh.addNode(p));
        s_.mesh.entity({3, volume_.tag}).nodes.push_back(column.back());
      } else {
        throw MeshError({3, volume_.tag}, "the sweep of " + nodeText(n) +
                                              " does not meet the mesh of the volume's boundary");
      }
    }
    return column;
  }

 private:
  const Sweep& s_;
  const ModelVolume& volume_;
  const ExtrusionMotion& motion_;
  std::set<NodeIndex> inside_;
  NodeLocator boundary_;
  std::vector<double> f_;
  std::map<NodeIndex, std::vector<NodeIndex>> columns_;
};

void append(EntityMesh& em, ElementType type, std::span<const NodeIndex> nodes) {
  ElementBlock& block = em.block(type);
  block.nodes.insert(block.nodes.end(), nodes.begin(), nodes.end());
}

// The prism a, b, c (bottom), d, e, f (top), positive; where vertical edges collapse on a
// rotation axis, the pyramid (one edge) or tetrahedron (two) that is left.
void addPrism(const Mesh& mesh, std::array<NodeIndex, 6> v, EntityMesh& em) {
  int collapsed = 0, still = 0, moving = 0;
  for (int i = 0; i < 3; ++i) {
    if (v[i] == v[i + 3]) ++collapsed, still = i;
    else moving = i;
  }
  if (collapsed == 0) {
    if (signedVolume(mesh, v[0], v[1], v[2], v[3]) < 0) {
      std::swap(v[1], v[2]);
      std::swap(v[4], v[5]);
    }
    append(em, ElementType::Prism6, v);
  } else if (collapsed == 1) {
    const int b = (still + 1) % 3, c = (still + 2) % 3;
    std::array<NodeIndex, 5> pyramid{v[b], v[c], v[c + 3], v[b + 3], v[still]};
    if (signedVolume(mesh, pyramid[0], pyramid[1], pyramid[3], pyramid[4]) < 0)
      std::swap(pyramid[1], pyramid[3]);
    append(em, ElementType::Pyramid5, pyramid);
  } else if (collapsed == 2) {
    std::array<NodeIndex, 4> tet{v[0], v[1], v[2], v[moving + 3]};
    if (signedVolume(mesh, tet[0], tet[1], tet[2], tet[3]) < 0) std::swap(tet[1], tet[2]);
    append(em, ElementType::Tet4, tet);
  }
}

// Prisms over the source triangles (Recombine) or three tetrahedra each.
void sweepTriangles(const Sweep& s, const ElementBlock& triangles, std::size_t layers,
                    bool recombine, Columns& columns, EntityMesh& em) {
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const auto t = triangles.element(e);
    const std::vector<NodeIndex>* c[3] = {&columns.of(t[0]), &columns.of(t[1]),
                                          &columns.of(t[2])};
    for (std::size_t k = 0; k < layers; ++k) {
      const std::array<NodeIndex, 6> prism{(*c[0])[k],     (*c[1])[k],     (*c[2])[k],
                                           (*c[0])[k + 1], (*c[1])[k + 1], (*c[2])[k + 1]};
      if (recombine)
        addPrism(s.mesh, prism, em);
      else
        splitPrism(s.mesh, prism, em.block(ElementType::Tet4).nodes);
    }
  }
}

// A hexahedron whose side on a rotation axis collapses: the prism that is left. Other
// collapses (a single corner on the axis) leave no element of the MSH format.
void addCollapsedHexahedron(const Mesh& mesh, const std::array<NodeIndex, 8>& hex, int collapsed,
                            int first, EntityMesh& em) {
  const int a = first == 0 && hex[3] == hex[7] ? 3 : first, b = (a + 1) % 4;
  if (collapsed != 2 || hex[b] != hex[b + 4])
    throw MeshError(em.entity, "a hexahedron touches the rotation axis at a corner only; "
                               "give the source surface triangles there");
  const int c = (a + 2) % 4, d = (a + 3) % 4;
  addPrism(mesh, {hex[a], hex[d], hex[d + 4], hex[b], hex[c], hex[c + 4]}, em);
}

// Hexahedra over the source quadrangles; Recombine is required.
void sweepQuadrangles(const Sweep& s, const ElementBlock& quads, std::size_t layers,
                      bool recombine, Columns& columns, EntityMesh& em) {
  const EntityId id = em.entity;
  if (!recombine && quads.size() > 0)
    throw MeshError(id, "its source surface has quadrangles, which only Recombine can sweep "
                        "(into hexahedra)");
  for (std::size_t e = 0; e < quads.size(); ++e) {
    const auto q = quads.element(e);
    const std::vector<NodeIndex>* c[4] = {&columns.of(q[0]), &columns.of(q[1]),
                                          &columns.of(q[2]), &columns.of(q[3])};
    for (std::size_t k = 0; k < layers; ++k) {
      std::array<NodeIndex, 8> hex;
      int collapsed = 0, first = -1;
      for (int v = 0; v < 4; ++v) {
        hex[v] = (*c[v])[k];
        hex[v + 4] = (*c[v])[k + 1];
        if (hex[v] == hex[v + 4]) ++collapsed, first = first < 0 ? v : first;
      }
      if (collapsed > 0) {
        addCollapsedHexahedron(s.mesh, hex, collapsed, first, em);
        continue;
      }
      if (signedVolume(s.mesh, hex[0], hex[1], hex[3], hex[4]) < 0) {
        std::swap(hex[1], hex[3]);
        std::swap(hex[5], hex[7]);
      }
      ElementBlock& hexes = em.block(ElementType::Hex8);
      hexes.nodes.insert(hexes.nodes.end(), hex.begin(), hex.end());
    }
  }
}

void meshSweptVolume(const Sweep& s, const ModelVolume& volume) {
  const EntityId id{3, volume.tag};
  const ExtrusionRecord& record = *volume.extrusion;
  const EntityMesh* source = s.mesh.find({2, record.source});
  if (!source || source->elementCount() == 0)
    throw MeshError(id, "its source surface " + std::to_string(record.source) + " has no mesh");
  std::vector<double> f = layerFractions(record.layers, id);
  const std::size_t layers = f.size() - 1;
  Columns columns(s, volume, *source, std::move(f));
  EntityMesh& em = s.mesh.entity(id);
  const bool recombine = record.layers.recombine;
  if (const ElementBlock* triangles = source->findBlock(ElementType::Triangle3))
    sweepTriangles(s, *triangles, layers, recombine, columns, em);
  if (const ElementBlock* quads = source->findBlock(ElementType::Quad4))
    sweepQuadrangles(s, *quads, layers, recombine, columns, em);
}

}  // namespace

bool isLayeredExtrusion(const ModelVolume& volume) { return hasLayers(volume.extrusion); }

bool boundsOnlyRecombinedExtrusions(const Model& model, int surfaceTag) {
  const std::vector<int> volumes = model.upward({2, surfaceTag});
  return !volumes.empty() && std::all_of(volumes.begin(), volumes.end(), [&](int tag) {
    const ModelVolume* v = model.volume(tag);
    return v && hasLayers(v->extrusion) && v->extrusion->layers.recombine;
  });
}

ExtrusionMesher::ExtrusionMesher(const Model& model) : model_(model) {
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

bool ExtrusionMesher::meshesVolume(int tag) const {
  const ModelVolume* volume = model_.volume(tag);
  return volume && hasLayers(volume->extrusion);
}

void ExtrusionMesher::meshSwept(EntityId id, Mesh& mesh) const {
  const Sweep s{model_, tolerance_, mesh};
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
  const Sweep s{model_, tolerance_, mesh};
  if (id.dim == 1)
    meshImageCurve(s, *model_.curve(id.tag), *record);
  else
    meshImageSurface(s, *model_.surface(id.tag), *record);
}

void ExtrusionMesher::meshVolumes(Mesh& mesh) const {
  const Sweep s{model_, tolerance_, mesh};
  for (const auto& [tag, volume] : model_.volumes())
    if (hasLayers(volume.extrusion)) meshSweptVolume(s, volume);
}

}  // namespace geomesh
