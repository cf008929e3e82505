// meshTransfiniteSurface: the structured grid by Coons interpolation, split per arrangement.
#include "mesh/structured/transfinite_surface.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesh/curves/curve_mesher.h"
#include "mesh/core/mesh_error.h"

namespace geomesh {
namespace {

using Side = std::vector<NodeIndex>;  // nodes from one corner to the next, both included
constexpr NodeIndex kNewNode = 0xffffffffu;

// The outer loop's nodes in order, each once, starting at its first curve's start.
std::vector<NodeIndex> loopNodes(const Model& model, const Mesh& mesh, const ModelSurface& s) {
  std::vector<NodeIndex> nodes;
  for (int curve : s.loops.front()) {
    const std::vector<NodeIndex> chain = curveNodeChain(model, mesh, curve);
    nodes.insert(nodes.end(), chain.begin(), chain.end() - 1);
  }
  return nodes;
}

std::vector<NodeIndex> cornerNodes(const Model& model, const Mesh& mesh, const ModelSurface& s,
                                   const TransfiniteSurface& constraint) {
  const EntityId id{2, s.tag};
  std::vector<NodeIndex> corners;
  if (!constraint.corners.empty()) {
    for (int point : constraint.corners) corners.push_back(pointNode(mesh, point));
    return corners;
  }
  const std::vector<int>& loop = s.loops.front();
  if (loop.size() != 3 && loop.size() != 4)
    throw MeshError(id, "a transfinite surface needs 3 or 4 corners; its boundary has " +
                            std::to_string(loop.size()) + " curves, so give them explicitly");
  for (int curve : loop) corners.push_back(curveNodeChain(model, mesh, curve).front());
  return corners;
}

// The boundary cut at the corners, starting at the first one.
std::vector<Side> sides(const Model& model, const Mesh& mesh, const ModelSurface& s,
                        const TransfiniteSurface& constraint) {
  const EntityId id{2, s.tag};
  if (s.loops.size() != 1) throw MeshError(id, "a transfinite surface cannot have holes");
  const std::vector<NodeIndex> corners = cornerNodes(model, mesh, s, constraint);
  if (corners.size() != 3 && corners.size() != 4)
    throw MeshError(id, "a transfinite surface needs 3 or 4 corners, not " +
                            std::to_string(corners.size()));
  std::vector<NodeIndex> loop = loopNodes(model, mesh, s);
  const auto first = std::find(loop.begin(), loop.end(), corners.front());
  if (first == loop.end()) throw MeshError(id, "corner 1 is not on the surface's boundary");
  std::rotate(loop.begin(), first, loop.end());
  loop.push_back(loop.front());
  std::vector<Side> result(1);
  for (std::size_t k = 0; k < loop.size(); ++k) {
    result.back().push_back(loop[k]);
    const bool corner = std::find(corners.begin(), corners.end(), loop[k]) != corners.end();
    if (corner && k > 0 && k + 1 < loop.size()) result.push_back({loop[k]});
  }
  if (result.size() != corners.size())
    throw MeshError(id, "its corners are not all on the boundary, or appear twice");
  return result;
}

// Normalised cumulative length along a chain of parameter points.
std::vector<double> fractions(const std::vector<Vec2>& chain) {
  std::vector<double> f{0};
  for (std::size_t k = 1; k < chain.size(); ++k) {
    const double du = chain[k].u - chain[k - 1].u, dv = chain[k].v - chain[k - 1].v;
    f.push_back(f.back() + std::sqrt(du * du + dv * dv));
  }
  for (double& x : f) x = f.back() > 0 ? x / f.back() : 0;
  return f;
}

// The structured grid: nodes (i, j), i < ni along the first side, j < nj along the last one
// reversed. Boundary rows and columns are the sides' nodes; on 3 sides, column 0 is the apex.
struct Grid {
  int ni = 0, nj = 0;
  bool apex = false;
  std::vector<NodeIndex> node;  // kNewNode where new
  std::vector<Vec2> uv;
  NodeIndex& at(int i, int j) { return node[static_cast<std::size_t>(j) * ni + i]; }
  Vec2& uvAt(int i, int j) { return uv[static_cast<std::size_t>(j) * ni + i]; }
};

Grid gridFromSides(const std::vector<Side>& s, EntityId id) {
  const bool apex = s.size() == 3;
  const Side& bottom = s[0];
  const Side& right = s[1];
  const Side& top = s[2];
  auto mismatch = [&](std::size_t a, std::size_t b, const char* what) {
    throw TransfiniteSidesMismatch(id, std::string("transfinite surface: ") + what + " have " +
                                           std::to_string(a) + " and " + std::to_string(b) +
                                           " nodes; they must have as many");
  };
  if (bottom.size() != top.size())
    mismatch(bottom.size(), top.size(), apex ? "the sides at the first corner" : "sides 1 and 3");
  if (!apex && right.size() != s[3].size()) mismatch(right.size(), s[3].size(), "sides 2 and 4");
  Grid g;
  g.ni = static_cast<int>(bottom.size());
  g.nj = static_cast<int>(right.size());
  g.apex = apex;
  g.node.assign(static_cast<std::size_t>(g.ni) * g.nj, kNewNode);
  g.uv.resize(g.node.size());
  for (int i = 0; i < g.ni; ++i) {
    g.at(i, 0) = bottom[i];
    g.at(i, g.nj - 1) = top[g.ni - 1 - i];
  }
  for (int j = 0; j < g.nj; ++j) {
    g.at(g.ni - 1, j) = right[j];
    g.at(0, j) = apex ? bottom.front() : s[3][g.nj - 1 - j];
  }
  return g;
}

// Coons interpolation of the boundary's parameters, with the blending parameters of each
// node taken from the lengths along the opposite sides.
void interpolate(Grid& g, const SurfaceGeometry& geometry, const Mesh& mesh) {
  for (std::size_t k = 0; k < g.node.size(); ++k)
    if (g.node[k] != kNewNode) g.uv[k] = geometry.project(mesh.node(g.node[k]));
  std::vector<Vec2> bottom, top, left, right;
  for (int i = 0; i < g.ni; ++i) bottom.push_back(g.uvAt(i, 0)), top.push_back(g.uvAt(i, g.nj - 1));
  for (int j = 0; j < g.nj; ++j) left.push_back(g.uvAt(0, j)), right.push_back(g.uvAt(g.ni - 1, j));
  const std::vector<double> ub = fractions(bottom), ut = fractions(top);
  const std::vector<double> vr = fractions(right);
  const std::vector<double> vl = g.apex ? vr : fractions(left);
  const Vec2 c00 = bottom.front(), c10 = bottom.back(), c01 = top.front(), c11 = top.back();
  for (int j = 1; j + 1 < g.nj; ++j)
    for (int i = 1; i + 1 < g.ni; ++i) {
      const double u = (1 - 0.5 * (vl[j] + vr[j])) * ub[i] + 0.5 * (vl[j] + vr[j]) * ut[i];
      const double v = (1 - u) * vl[j] + u * vr[j];
      auto blend = [&](double Vec2::*c) {
        return (1 - v) * bottom[i].*c + v * top[i].*c + (1 - u) * left[j].*c + u * right[j].*c -
               ((1 - u) * (1 - v) * c00.*c + u * (1 - v) * c10.*c + u * v * c11.*c +
                (1 - u) * v * c01.*c);
      };
      g.uvAt(i, j) = {blend(&Vec2::u), blend(&Vec2::v)};
    }
}

void addInteriorNodes(Grid& g, const SurfaceGeometry& geometry, EntityMesh& em, Mesh& mesh) {
  for (int j = 1; j + 1 < g.nj; ++j)
    for (int i = 1; i + 1 < g.ni; ++i) {
      const Vec2 uv = g.uvAt(i, j);
      const NodeIndex n = mesh.addNode(geometry.point(uv));
      g.at(i, j) = n;
      em.nodes.push_back(n);
      em.parametric.insert(em.parametric.end(), {uv.u, uv.v});
    }
  for (int j = 1; j + 1 < g.nj; ++j)
    for (int i = 1; i + 1 < g.ni; ++i) {
      const Vec3 x = mesh.node(g.at(i, j));
      const double h = 0.25 * (distance(x, mesh.node(g.at(i - 1, j))) +
                               distance(x, mesh.node(g.at(i + 1, j))) +
                               distance(x, mesh.node(g.at(i, j - 1))) +
                               distance(x, mesh.node(g.at(i, j + 1))));
      mesh.setNodeSize(g.at(i, j), h);
    }
}

bool leftDiagonal(TransfiniteSurface::Arrangement a, int i, int j) {
  using A = TransfiniteSurface::Arrangement;
  const bool odd = (i + j) % 2 != 0;
  switch (a) {
    case A::Left: return true;
    case A::Right: return false;
    // As in Gmsh, AlternateLeft starts with a right diagonal in the first cell.
    case A::AlternateLeft: return odd;
    case A::AlternateRight: return !odd;
  }
  return true;
}

// Counter-clockwise in the grid's (i, j) orientation; flipped afterwards if that is clockwise
// in the parametrization.
void addElements(Grid& g, const TransfiniteSurface& constraint, bool recombine, EntityMesh& em) {
  std::vector<NodeIndex> triangles, quads;
  for (int j = 0; j + 1 < g.nj; ++j)
    for (int i = 0; i + 1 < g.ni; ++i) {
      const NodeIndex a = g.at(i, j), b = g.at(i + 1, j), c = g.at(i + 1, j + 1),
                      d = g.at(i, j + 1);
      if (g.apex && i == 0) {
        triangles.insert(triangles.end(), {a, b, c});
      } else if (recombine) {
        quads.insert(quads.end(), {a, b, c, d});
      } else if (leftDiagonal(constraint.arrangement, i, j)) {
        triangles.insert(triangles.end(), {a, b, d, d, b, c});
      } else {
        triangles.insert(triangles.end(), {a, b, c, a, c, d});
      }
    }
  if (!triangles.empty()) em.block(ElementType::Triangle3).nodes = std::move(triangles);
  if (!quads.empty()) em.block(ElementType::Quad4).nodes = std::move(quads);
}

// +1 if the grid runs counter-clockwise in the parameter plane, else -1.
double gridOrientation(Grid& g) {
  double area = 0;
  for (int j = 0; j + 1 < g.nj; ++j)
    for (int i = 0; i + 1 < g.ni; ++i) {
      const Vec2 a = g.uvAt(i, j), b = g.uvAt(i + 1, j), c = g.uvAt(i + 1, j + 1);
      const Vec2 d = g.uvAt(i, j + 1);
      area += (c.u - a.u) * (d.v - b.v) - (c.v - a.v) * (d.u - b.u);
    }
  return area >= 0 ? 1 : -1;
}

void reverseElements(EntityMesh& em) {
  for (ElementBlock& block : em.blocks) {
    const std::size_t n = static_cast<std::size_t>(nodeCount(block.type));
    for (std::size_t e = 0; e < block.size(); ++e)
      std::reverse(block.nodes.begin() + static_cast<std::ptrdiff_t>(e * n + 1),
                   block.nodes.begin() + static_cast<std::ptrdiff_t>((e + 1) * n));
  }
}

}  // namespace

void meshTransfiniteSurface(const Model& model, const ModelSurface& surface,
                            const TransfiniteSurface& constraint, bool recombine, Mesh& mesh) {
  const EntityId id{2, surface.tag};
  if (!surface.geometry) throw MeshError(id, "surface has no geometry");
  if (surface.loops.empty()) throw MeshError(id, "surface has no boundary");
  if (!surface.embeddedPoints.empty() || !surface.embeddedCurves.empty())
    throw MeshError(id, "a transfinite surface cannot have embedded points or curves");
  Grid grid = gridFromSides(sides(model, mesh, surface, constraint), id);
  interpolate(grid, *surface.geometry, mesh);
  EntityMesh& em = mesh.entity(id);
  em.nodes.clear();
  em.parametric.clear();
  em.blocks.clear();
  addInteriorNodes(grid, *surface.geometry, em, mesh);
  addElements(grid, constraint, recombine, em);
  if (gridOrientation(grid) < 0) reverseElements(em);
}

}  // namespace geomesh
