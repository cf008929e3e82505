// meshSweptVolume: a layered sweep of a surface into prisms, hexahedra or tetrahedra.
#include "mesh/structured/swept_volume.h"

#include <algorithm>
#include <array>
#include <set>
#include <span>

#include "mesh/core/mesh_error.h"

namespace geomesh::extrusion {
namespace {

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

// The nodes of each source node's sweep, layer by layer: the boundary's nodes where the sweep
// meets it (found by position), new nodes of the volume elsewhere.
class Columns {
 public:
  Columns(const Sweep& s, const ModelVolume& volume, const EntityMesh& source,
          std::vector<double> fractions)
      : s_(s),
        volume_(volume),
        record_(*volume.extrusion),
        inside_(source.nodes.begin(), source.nodes.end()),
        boundary_(closureLocator(s.model, s.mesh, {3, volume.tag}, s.tolerance)),
        f_(std::move(fractions)) {}

  const std::vector<NodeIndex>& of(NodeIndex n) {
    auto [it, added] = columns_.try_emplace(n);
    if (!added) return it->second;
    std::vector<NodeIndex>& column = it->second;
    column.push_back(n);
    for (std::size_t k = 1; k < f_.size(); ++k) {
      const Vec3 p = sweptPoint(s_, record_, s_.mesh.node(n), f_[k], {3, volume_.tag});
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
  const ExtrusionRecord& record_;
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

}  // namespace

void meshSweptVolume(const Sweep& s, const ModelVolume& volume) {
  const EntityId id{3, volume.tag};
  const ExtrusionRecord& record = *volume.extrusion;
  const EntityMesh* source = s.mesh.find({2, record.source});
  if (!source || source->elementCount() == 0)
    throw MeshError(id, "its source surface " + std::to_string(record.source) + " has no mesh");
  std::vector<double> f = sweepFractions(record, id);
  const std::size_t layers = f.size() - 1;
  Columns columns(s, volume, *source, std::move(f));
  EntityMesh& em = s.mesh.entity(id);
  const bool recombine = record.layers.recombine;
  if (const ElementBlock* triangles = source->findBlock(ElementType::Triangle3))
    sweepTriangles(s, *triangles, layers, recombine, columns, em);
  if (const ElementBlock* quads = source->findBlock(ElementType::Quad4))
    sweepQuadrangles(s, *quads, layers, recombine, columns, em);
}

}  // namespace geomesh::extrusion
