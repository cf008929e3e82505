// buildSurfaceLayer: walls from the surface's loops, column nodes, layer elements, fronts.
#include "mesh/surfaces/boundary_layer_2d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "mesh/curves/curve_mesher.h"
#include "mesh/surfaces/layer_columns.h"

namespace geomesh {
namespace {

// An orthonormal frame of a plane, oriented as the surface's parameters.
struct PlaneFrame {
  Vec3 origin, e1, e2;
  Vec2 flat(Vec3 p) const { return {dot(p - origin, e1), dot(p - origin, e2)}; }
  Vec3 space(Vec2 q) const { return origin + q.u * e1 + q.v * e2; }
};

PlaneFrame planeFrame(const SurfaceGeometry& g) {
  const ParamBox box = g.bounds();
  Vec2 middle{0, 0};
  if (std::isfinite(box.u.min + box.u.max + box.v.min + box.v.max))
    middle = {0.5 * (box.u.min + box.u.max), 0.5 * (box.v.min + box.v.max)};
  const SurfaceDerivatives d = g.firstDerivatives(middle);
  const Vec3 e1 = normalized(d.du);
  const Vec3 e2 = normalized(d.dv - dot(d.dv, e1) * e1);
  return {g.point(middle), e1, e2};
}

// The first field asking for a layer on curve `curve` of surface `surface`.
const BoundaryLayerParameters* layerOf(std::span<const BoundaryLayerParameters* const> layers,
                                       int curve, int surface) {
  for (const BoundaryLayerParameters* p : layers)
    if (p->hasCurve(curve) && !p->excludes(surface)) return p;
  return nullptr;
}

// One loop as nodes in loop order, with their model points and the layer of each segment.
struct LoopNodes {
  std::vector<NodeIndex> nodes;
  LayerWall wall;
};

LoopNodes loopNodes(const Model& model, const Mesh& mesh, const std::vector<int>& loop,
                    std::span<const BoundaryLayerParameters* const> layers, int surface,
                    const PlaneFrame& frame) {
  LoopNodes out;
  for (int signedCurve : loop) {
    const std::vector<NodeIndex> chain = curveNodeChain(model, mesh, signedCurve);
    const ModelCurve* curve = model.curve(std::abs(signedCurve));
    const BoundaryLayerParameters* layer = layerOf(layers, std::abs(signedCurve), surface);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      out.nodes.push_back(chain[k]);
      out.wall.xy.push_back(frame.flat(mesh.node(chain[k])));
      int point = 0;
      if (k == 0 && curve) point = signedCurve > 0 ? curve->startPoint : curve->endPoint;
      out.wall.point.push_back(point);
      out.wall.layer.push_back(layer);
    }
  }
  return out;
}

double signedArea(const std::vector<Vec2>& xy) {
  double area = 0;
  for (std::size_t k = 0; k < xy.size(); ++k) {
    const Vec2 a = xy[k], b = xy[(k + 1) % xy.size()];
    area += a.u * b.v - a.v * b.u;
  }
  return 0.5 * area;
}

std::string place(Vec3 p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
  return text;
}

// The mean length of the wall segments at node i: the size the front keeps there.
double wallSpacing(const LayerWall& wall, std::size_t i) {
  const std::size_t n = wall.xy.size();
  const Vec2 a = wall.xy[(i + n - 1) % n], b = wall.xy[i], c = wall.xy[(i + 1) % n];
  return 0.5 * (std::hypot(b.u - a.u, b.v - a.v) + std::hypot(c.u - b.u, c.v - b.v));
}

// The nodes of each column point (the base is the wall node), made in the mesh and the
// surface's mesh.
using ColumnNodes = std::vector<std::vector<std::vector<NodeIndex>>>;  // node, column, level

ColumnNodes makeNodes(const LoopNodes& loop, const WallColumns& columns, const PlaneFrame& frame,
                      const SurfaceGeometry& g, Mesh& mesh, EntityMesh& em) {
  ColumnNodes ids(columns.size());
  for (std::size_t i = 0; i < columns.size(); ++i)
    for (const LayerColumn& c : columns[i]) {
      std::vector<NodeIndex> column{loop.nodes[i]};
      for (std::size_t k = 1; k <= c.levels; ++k) {
        const Vec3 p = frame.space(c.at(k));
        const NodeIndex node = mesh.addNode(p);
        mesh.setNodeSize(node, wallSpacing(loop.wall, i));
        const Vec2 uv = g.project(p);
        em.nodes.push_back(node);
        em.parametric.insert(em.parametric.end(), {uv.u, uv.v});
        column.push_back(node);
      }
      ids[i].push_back(std::move(column));
    }
  return ids;
}

// The layer's elements of one wall, counter-clockwise in the parameters.
void addElements(const LoopNodes& loop, const WallColumns& columns, const ColumnNodes& ids,
                 SurfaceLayer& layer) {
  const std::size_t n = columns.size();
  forEachCell(loop.wall, columns, [&](const LayerCell& cell) {
    const std::size_t nodeB = cell.acrossSegment ? (cell.node + 1) % n : cell.node;
    const std::vector<NodeIndex>& a = ids[cell.node][cell.a];
    const std::vector<NodeIndex>& b = ids[nodeB][cell.b];
    auto clamp = [](const std::vector<NodeIndex>& c, std::size_t k) {
      return c[std::min(k, c.size() - 1)];
    };
    const NodeIndex ring[4] = {clamp(a, cell.level), clamp(b, cell.level), clamp(b, cell.level + 1),
                               clamp(a, cell.level + 1)};
    std::vector<NodeIndex> corners;
    for (NodeIndex v : ring)
      if (corners.empty() || corners.back() != v) corners.push_back(v);
    while (corners.size() > 1 && corners.back() == corners.front()) corners.pop_back();
    if (corners.size() < 3) return;
    if (!loop.wall.domainLeft) std::reverse(corners.begin(), corners.end());
    const BoundaryLayerParameters& p = *loop.wall.layer[cell.node];
    if (corners.size() == 3) {
      layer.triangles.insert(layer.triangles.end(), corners.begin(), corners.end());
    } else if (p.quads) {
      layer.quadrangles.insert(layer.quadrangles.end(), corners.begin(), corners.end());
    } else {
      layer.triangles.insert(layer.triangles.end(), {corners[0], corners[1], corners[2]});
      layer.triangles.insert(layer.triangles.end(), {corners[0], corners[2], corners[3]});
    }
  });
}

// The front of one wall: the wall where it has no layer, the columns' tops where it has, and
// up or down a column where a layer starts or ends.
void addFront(const LoopNodes& loop, const WallColumns& columns, const ColumnNodes& ids,
              const SurfaceGeometry& g, const Mesh& mesh, SurfaceLayer& layer) {
  const std::size_t n = columns.size();
  std::vector<NodeIndex> front;
  std::vector<double> sizes;
  auto emit = [&](NodeIndex v, double size) {
    if (!front.empty() && front.back() == v) return;
    front.push_back(v);
    sizes.push_back(size);
  };
  for (std::size_t i = 0; i < n; ++i) {
    const double size = wallSpacing(loop.wall, i);
    if (columns[i].empty()) {
      emit(loop.nodes[i], size);
      continue;
    }
    const std::vector<std::vector<NodeIndex>>& here = ids[i];
    if (columns[(i + n - 1) % n].empty())
      for (NodeIndex v : here.front()) emit(v, size);
    for (const std::vector<NodeIndex>& c : here) emit(c.back(), size);
    if (columns[(i + 1) % n].empty())
      for (auto v = here.back().rbegin(); v != here.back().rend(); ++v) emit(*v, size);
  }
  while (front.size() > 1 && front.back() == front.front()) front.pop_back(), sizes.pop_back();
  std::vector<Vec2> uv;
  for (NodeIndex v : front) uv.push_back(g.project(mesh.node(v)));
  layer.fronts.push_back(std::move(front));
  layer.frontParameters.push_back(std::move(uv));
  layer.frontSizes.push_back(std::move(sizes));
}

bool asksForLayer(const ModelSurface& surface,
                  std::span<const BoundaryLayerParameters* const> layers) {
  for (const std::vector<int>& loop : surface.loops)
    for (int curve : loop)
      if (layerOf(layers, std::abs(curve), surface.tag)) return true;
  return false;
}

}  // namespace

std::optional<SurfaceLayer> buildSurfaceLayer(
    const Model& model, const ModelSurface& surface,
    std::span<const BoundaryLayerParameters* const> layers, int fanElements,
    const SizeFields& fields, Mesh& mesh, EntityMesh& em) {
  if (!surface.geometry || !asksForLayer(surface, layers)) return std::nullopt;
  const SurfaceGeometry& g = *surface.geometry;
  if (!g.isPlane()) {
    fields.warning("surface " + std::to_string(surface.tag) +
                   " is not plane: the boundary layer asked on its curves is not built there "
                   "(2D layers are made on plane surfaces); it is meshed without one");
    return std::nullopt;
  }
  const PlaneFrame frame = planeFrame(g);
  std::vector<LoopNodes> loops;
  std::vector<LayerWall> walls;
  for (std::size_t k = 0; k < surface.loops.size(); ++k) {
    loops.push_back(loopNodes(model, mesh, surface.loops[k], layers, surface.tag, frame));
    LayerWall& wall = loops.back().wall;
    wall.domainLeft = (k == 0) == (signedArea(wall.xy) > 0);
    walls.push_back(wall);
  }
  std::vector<WallColumns> columns;
  for (const LayerWall& wall : walls) columns.push_back(layerColumns(wall, fanElements));
  const std::vector<Vec2> shortened = limitColumns(walls, columns);
  if (!shortened.empty())
    fields.warning("boundary layer of surface " + std::to_string(surface.tag) + " shortened at " +
                   std::to_string(shortened.size()) + " node(s), first near " +
                   place(frame.space(shortened.front())) +
                   ": its columns would cross each other or reach another wall");
  const bool any = std::any_of(columns.begin(), columns.end(), [](const WallColumns& w) {
    return std::any_of(w.begin(), w.end(), [](const auto& node) { return !node.empty(); });
  });
  if (!any) return std::nullopt;
  SurfaceLayer layer;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const ColumnNodes ids = makeNodes(loops[k], columns[k], frame, g, mesh, em);
    addElements(loops[k], columns[k], ids, layer);
    addFront(loops[k], columns[k], ids, g, mesh, layer);
  }
  return layer;
}

}  // namespace geomesh
