// Reference elements of every type, built from integer lattices: vertices first, then the nodes
// of each edge from its first vertex to its second, then each face's interior nodes as an
// element of lower order on that face, then the interior as an element of lower order inside.
#include "mesh/high_order/reference_element.h"

#include <map>
#include <mutex>
#include <span>
#include <stdexcept>

namespace geomesh {
namespace {

using Lattice = std::array<int, 3>;

struct FamilyTopology {
  std::vector<std::vector<int>> edges;
  std::vector<std::vector<int>> faces;  // 3 or 4 vertices each, for volume families
  int interiorShrink = 0;  // the interior is an element of order p - interiorShrink; 0: none
};

const FamilyTopology& topology(ElementFamily f) {
  static const FamilyTopology point{}, line{{{0, 1}}, {}, 0};
  static const FamilyTopology triangle{{{0, 1}, {1, 2}, {2, 0}}, {}, 3};
  static const FamilyTopology quad{{{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {}, 2};
  static const FamilyTopology tet{{{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}},
                                  {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {3, 1, 2}},
                                  4};
  static const FamilyTopology hex{
      {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3}, {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6},
       {6, 7}},
      {{0, 3, 2, 1}, {0, 1, 5, 4}, {0, 4, 7, 3}, {1, 2, 6, 5}, {2, 3, 7, 6}, {4, 5, 6, 7}},
      2};
  static const FamilyTopology prism{
      {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4}, {2, 5}, {3, 4}, {3, 5}, {4, 5}},
      {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}},
      0};
  static const FamilyTopology pyramid{
      {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 4}, {2, 3}, {2, 4}, {3, 4}},
      {{0, 1, 4}, {3, 0, 4}, {1, 2, 4}, {2, 3, 4}, {0, 3, 2, 1}},
      3};
  switch (f) {
    case ElementFamily::Point: return point;
    case ElementFamily::Line: return line;
    case ElementFamily::Triangle: return triangle;
    case ElementFamily::Quad: return quad;
    case ElementFamily::Tet: return tet;
    case ElementFamily::Hex: return hex;
    case ElementFamily::Prism: return prism;
    case ElementFamily::Pyramid: return pyramid;
  }
  return point;
}

// The vertices of a family's lattice of order p.
std::vector<Lattice> corners(ElementFamily f, int p) {
  switch (f) {
    case ElementFamily::Point: return {{0, 0, 0}};
    case ElementFamily::Line: return {{0, 0, 0}, {p, 0, 0}};
    case ElementFamily::Triangle: return {{0, 0, 0}, {p, 0, 0}, {0, p, 0}};
    case ElementFamily::Quad: return {{0, 0, 0}, {p, 0, 0}, {p, p, 0}, {0, p, 0}};
    case ElementFamily::Tet: return {{0, 0, 0}, {p, 0, 0}, {0, p, 0}, {0, 0, p}};
    case ElementFamily::Hex:
      return {{0, 0, 0}, {p, 0, 0}, {p, p, 0}, {0, p, 0},
              {0, 0, p}, {p, 0, p}, {p, p, p}, {0, p, p}};
    case ElementFamily::Prism:
      return {{0, 0, 0}, {p, 0, 0}, {0, p, 0}, {0, 0, p}, {p, 0, p}, {0, p, p}};
    case ElementFamily::Pyramid: return {{0, 0, 0}, {p, 0, 0}, {p, p, 0}, {0, p, 0}, {0, 0, p}};
  }
  return {};
}

std::array<double, 3> toReference(ElementFamily f, const Lattice& l, int p) {
  const double i = l[0], j = l[1], k = l[2], q = p == 0 ? 1 : p;
  switch (f) {
    case ElementFamily::Line: return {-1 + 2 * i / q, 0, 0};
    case ElementFamily::Quad: return {-1 + 2 * i / q, -1 + 2 * j / q, 0};
    case ElementFamily::Hex: return {-1 + 2 * i / q, -1 + 2 * j / q, -1 + 2 * k / q};
    case ElementFamily::Prism: return {i / q, j / q, -1 + 2 * k / q};
    case ElementFamily::Pyramid: return {(2 * i + k - q) / q, (2 * j + k - q) / q, k / q};
    default: return {i / q, j / q, k / q};
  }
}

struct LatticeNode {
  Lattice at;
  NodePlace place;
};

Lattice along(const Lattice& a, const Lattice& b, const Lattice& d, int s, int t, int p) {
  Lattice r{};
  for (int c = 0; c < 3; ++c) r[c] = a[c] + (s * (b[c] - a[c]) + t * (d[c] - a[c])) / p;
  return r;
}

std::vector<LatticeNode> latticeNodes(ElementFamily f, int p, bool serendipity);

// Interior nodes of a triangle or quadrangle face (corners given) of an element of order p.
void appendFaceInterior(std::span<const int> face, const std::vector<Lattice>& at, int p,
                        NodePlace::Kind kind, std::vector<LatticeNode>& out) {
  const bool triangle = face.size() == 3;
  const int q = p - (triangle ? 3 : 2);
  if (q < 0) return;
  const Lattice& a = at[face[0]];
  const Lattice& b = at[face[1]];
  const Lattice& d = at[face[triangle ? 2 : 3]];
  for (const LatticeNode& inner :
       latticeNodes(triangle ? ElementFamily::Triangle : ElementFamily::Quad, q, false)) {
    const int s = inner.at[0] + 1, t = inner.at[1] + 1;
    NodePlace place{kind, static_cast<std::uint8_t>(face.size()), {}, {}, 1};
    for (std::size_t c = 0; c < face.size(); ++c) place.corners[c] = face[c];
    if (triangle) {
      place.weights = {static_cast<std::uint16_t>(p - s - t), static_cast<std::uint16_t>(s),
                       static_cast<std::uint16_t>(t), 0};
      place.total = p;
    } else {
      place.weights = {static_cast<std::uint16_t>((p - s) * (p - t)),
                       static_cast<std::uint16_t>(s * (p - t)), static_cast<std::uint16_t>(s * t),
                       static_cast<std::uint16_t>((p - s) * t)};
      place.total = p * p;
    }
    out.push_back({along(a, b, d, s, t, p), place});
  }
}

std::vector<LatticeNode> latticeNodes(ElementFamily f, int p, bool serendipity) {
  const std::vector<Lattice> at = corners(f, p);
  std::vector<LatticeNode> out;
  if (p == 0) {
    out.push_back({{0, 0, 0}, {NodePlace::Cell, 0, {}, {}, 1}});
    return out;
  }
  for (std::size_t v = 0; v < at.size(); ++v)
    out.push_back({at[v], {NodePlace::Vertex, 1, {static_cast<std::uint8_t>(v)}, {1}, 1}});
  const FamilyTopology& topo = topology(f);
  for (const std::vector<int>& e : topo.edges)
    for (int t = 1; t < p; ++t) {
      const NodePlace place{NodePlace::Edge,
                            2,
                            {static_cast<std::uint8_t>(e[0]), static_cast<std::uint8_t>(e[1])},
                            {static_cast<std::uint16_t>(p - t), static_cast<std::uint16_t>(t)},
                            static_cast<std::uint16_t>(p)};
      out.push_back({along(at[e[0]], at[e[1]], at[e[0]], t, 0, p), place});
    }
  if (serendipity) return out;
  const int dim = dimension(f);
  if (dim == 2) {
    const std::vector<int> all = f == ElementFamily::Triangle ? std::vector<int>{0, 1, 2}
                                                              : std::vector<int>{0, 1, 2, 3};
    appendFaceInterior(all, at, p, NodePlace::Face, out);
    return out;
  }
  if (dim < 3) return out;
  for (const std::vector<int>& face : topo.faces) appendFaceInterior(face, at, p, NodePlace::Face, out);
  if (topo.interiorShrink == 0 || p - topo.interiorShrink < 0) return out;
  for (const LatticeNode& inner : latticeNodes(f, p - topo.interiorShrink, false))
    out.push_back({{inner.at[0] + 1, inner.at[1] + 1, inner.at[2] + 1},
                   {NodePlace::Cell, 0, {}, {}, 1}});
  return out;
}

ReferenceElement build(ElementType type) {
  const ElementTypeInfo& info = elementInfo(type);
  if (info.family == ElementFamily::Prism && info.order > 2)
    throw std::logic_error("prisms above order 2 have no node layout");
  ReferenceElement r;
  r.type = type;
  r.family = info.family;
  r.order = info.order;
  for (const LatticeNode& node : latticeNodes(info.family, info.order, info.serendipity)) {
    r.xi.push_back(toReference(info.family, node.at, info.order));
    r.places.push_back(node.place);
  }
  if (static_cast<int>(r.xi.size()) != info.nodes)
    throw std::logic_error(std::string("reference element of ") + info.name + " has " +
                           std::to_string(r.xi.size()) + " nodes");
  return r;
}

}  // namespace

const ReferenceElement& referenceElement(ElementType type) {
  static std::mutex mutex;
  static std::map<ElementType, ReferenceElement> built;
  const std::lock_guard lock(mutex);
  auto it = built.find(type);
  if (it == built.end()) it = built.emplace(type, build(type)).first;
  return it->second;
}

void linearShapeFunctions(ElementFamily family, const std::array<double, 3>& xi, double* n) {
  const double x = xi[0], y = xi[1], z = xi[2];
  switch (family) {
    case ElementFamily::Point: n[0] = 1; return;
    case ElementFamily::Line: n[0] = (1 - x) / 2, n[1] = (1 + x) / 2; return;
    case ElementFamily::Triangle: n[0] = 1 - x - y, n[1] = x, n[2] = y; return;
    case ElementFamily::Quad:
      n[0] = (1 - x) * (1 - y) / 4, n[1] = (1 + x) * (1 - y) / 4;
      n[2] = (1 + x) * (1 + y) / 4, n[3] = (1 - x) * (1 + y) / 4;
      return;
    case ElementFamily::Tet: n[0] = 1 - x - y - z, n[1] = x, n[2] = y, n[3] = z; return;
    case ElementFamily::Hex:
      for (int v = 0; v < 8; ++v) {
        const double sx = (v == 1 || v == 2 || v == 5 || v == 6) ? 1 : -1;
        const double sy = (v == 2 || v == 3 || v == 6 || v == 7) ? 1 : -1;
        const double sz = v >= 4 ? 1 : -1;
        n[v] = (1 + sx * x) * (1 + sy * y) * (1 + sz * z) / 8;
      }
      return;
    case ElementFamily::Prism: {
      const double t[3] = {1 - x - y, x, y};
      for (int v = 0; v < 3; ++v) n[v] = t[v] * (1 - z) / 2, n[v + 3] = t[v] * (1 + z) / 2;
      return;
    }
    case ElementFamily::Pyramid: {
      // Bilinear on each horizontal slice of the shrinking square, apex on top.
      const double s = 1 - z;
      const double u = s > 1e-14 ? x / s : 0, v = s > 1e-14 ? y / s : 0;
      n[0] = s * (1 - u) * (1 - v) / 4, n[1] = s * (1 + u) * (1 - v) / 4;
      n[2] = s * (1 + u) * (1 + v) / 4, n[3] = s * (1 - u) * (1 + v) / 4;
      n[4] = z;
      return;
    }
  }
}

Vec3 linearImage(ElementFamily family, const std::array<double, 3>& xi,
                 std::span<const Vec3> corners) {
  double n[8];
  linearShapeFunctions(family, xi, n);
  Vec3 x{0, 0, 0};
  for (int v = 0; v < vertexCount(family); ++v) x += corners[v] * n[v];
  return x;
}

}  // namespace geomesh
