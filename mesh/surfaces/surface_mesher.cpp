#include "mesh/surfaces/surface_mesher.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unordered_map>
#include <utility>

#include "mesh/surfaces/constrained_delaunay.h"
#include "mesh/curves/curve_mesher.h"
#include "mesh/core/mesh_error.h"
#include "mesh/surfaces/surface_metric.h"

namespace geomesh {
namespace {

// The nodes and constrained segments a surface's triangulation starts from, numbered locally.
struct SurfaceInput {
  std::vector<NodeIndex> nodes;
  std::vector<ConstrainedSegment> segments;
  std::vector<int> segmentCurve;  // tag of the curve each segment comes from
  std::unordered_map<NodeIndex, std::uint32_t> localOf;

  std::uint32_t local(NodeIndex n) {
    const auto [it, inserted] = localOf.try_emplace(n, static_cast<std::uint32_t>(nodes.size()));
    if (inserted) nodes.push_back(n);
    return it->second;
  }
  void addCurve(const Model& model, const Mesh& mesh, int signedTag, EdgeKind kind) {
    const std::vector<NodeIndex> chain = curveNodeChain(model, mesh, signedTag);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      segments.push_back({local(chain[k]), local(chain[k + 1]), kind});
      segmentCurve.push_back(std::abs(signedTag));
    }
  }
};

SurfaceInput collectInput(const Model& model, const ModelSurface& surface, const Mesh& mesh) {
  SurfaceInput in;
  for (const std::vector<int>& loop : surface.loops)
    for (int curve : loop) in.addCurve(model, mesh, curve, EdgeKind::Boundary);
  for (int curve : surface.embeddedCurves) in.addCurve(model, mesh, curve, EdgeKind::Embedded);
  for (int point : surface.embeddedPoints) in.local(pointNode(mesh, point));
  return in;
}

std::vector<Vec2> parameters(const SurfaceGeometry& g, const Mesh& mesh,
                             const std::vector<NodeIndex>& nodes) {
  std::vector<Vec2> uv;
  uv.reserve(nodes.size());
  for (NodeIndex n : nodes) uv.push_back(g.project(mesh.node(n)));
  return uv;
}

Vec2 boxCenter(const std::vector<Vec2>& points) {
  Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (Vec2 p : points) {
    lo = {std::min(lo.u, p.u), std::min(lo.v, p.v)};
    hi = {std::max(hi.u, p.u), std::max(hi.v, p.v)};
  }
  return {0.5 * (lo.u + hi.u), 0.5 * (lo.v + hi.v)};
}

std::string text(Vec3 p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
  return buffer;
}

// The constrained Delaunay triangulation of the input, boundary edges recovered.
Triangulation2D triangulateBoundary(const SurfaceInput& in, const std::vector<Vec2>& work,
                                    EntityId id, const Mesh& mesh) {
  Triangulation2D tri = delaunayTriangulation(work);
  constexpr std::uint32_t first = Triangulation2D::kFirstVertex;
  for (std::uint32_t k = 0; k < in.nodes.size(); ++k)
    if (tri.triangleOf(k + first) == kNone)
      throw MeshError(id, "boundary node " + std::to_string(in.nodes[k] + 1) +
                              " coincides with another one in the parameter plane");
  std::vector<ConstrainedSegment> segments = in.segments;
  for (ConstrainedSegment& s : segments) s.a += first, s.b += first;
  const long failed = recoverSegments(tri, segments);
  if (failed >= 0) {
    const std::size_t k = static_cast<std::size_t>(failed);
    const Vec3 a = mesh.node(in.nodes[in.segments[k].a]);
    const Vec3 b = mesh.node(in.nodes[in.segments[k].b]);
    throw MeshError(id, "cannot recover the edge from " + text(a) + " to " + text(b) +
                            " of curve " + std::to_string(in.segmentCurve[k]) +
                            ": boundary curves intersect or pass through a node");
  }
  return tri;
}

// Sets the target sizes at the triangulation's vertices. Extended from the boundary: the mean
// length of the boundary segments at each boundary node (what the curve meshes actually realised,
// so that the interior matches them), or the node's own size for an isolated embedded point. Not
// extended: sizeMax everywhere.
void setBoundarySizes(const SurfaceInput& in, const SizeRules& rules, const Mesh& mesh,
                      Triangulation2D& tri) {
  constexpr std::uint32_t first = Triangulation2D::kFirstVertex;
  if (!rules.extendFromBoundary) {
    for (std::uint32_t k = 0; k < in.nodes.size(); ++k)
      tri.setSize(k + first, rules.finish(rules.sizeMax));
    return;
  }
  std::vector<double> total(in.nodes.size(), 0.0);
  std::vector<int> count(in.nodes.size(), 0);
  for (const ConstrainedSegment& s : in.segments) {
    const double length = distance(mesh.node(in.nodes[s.a]), mesh.node(in.nodes[s.b]));
    total[s.a] += length, total[s.b] += length;
    ++count[s.a], ++count[s.b];
  }
  const double fallback = rules.finish(rules.defaultSize);
  for (std::uint32_t k = 0; k < in.nodes.size(); ++k) {
    const NodeIndex n = in.nodes[k];
    if (count[k] > 0)
      tri.setSize(k + first, total[k] / count[k]);
    else
      tri.setSize(k + first, mesh.nodeSize(n) > 0 ? mesh.nodeSize(n) : fallback);
  }
}

// Copies the triangles and their new vertices into the surface's EntityMesh.
void storeMesh(const PlanarMesh& planar, const SurfaceInput& in, const WorkFrame& frame,
               const SurfaceGeometry& g, EntityMesh& em, Mesh& mesh) {
  constexpr std::uint32_t first = Triangulation2D::kFirstVertex;
  const std::uint32_t boundaryEnd = first + static_cast<std::uint32_t>(in.nodes.size());
  const std::uint32_t pointCount = static_cast<std::uint32_t>(planar.points.size());
  std::vector<NodeIndex> globalOf(pointCount, kNone);
  for (std::uint32_t k = 0; k < in.nodes.size(); ++k) globalOf[k + first] = in.nodes[k];
  std::vector<std::uint8_t> used(pointCount, 0);
  for (std::uint32_t v : planar.triangles) used[v] = 1;
  for (std::uint32_t v = boundaryEnd; v < pointCount; ++v) {
    if (!used[v]) continue;
    const Vec2 uv = frame.toParam(planar.points[v]);
    const NodeIndex node = mesh.addNode(g.point(uv));
    globalOf[v] = node;
    em.nodes.push_back(node);
    em.parametric.insert(em.parametric.end(), {uv.u, uv.v});
    mesh.setNodeSize(node, planar.sizes[v]);
  }
  ElementBlock& triangles = em.block(ElementType::Triangle3);
  for (std::uint32_t v : planar.triangles) triangles.nodes.push_back(globalOf[v]);
}

}  // namespace

void meshSurface(const Model& model, const ModelSurface& surface, const SizeRules& rules,
                 int smoothingPasses, Mesh& mesh, const SizeFields* fields,
                 const SurfaceAlgorithm& algorithm) {
  const EntityId id{2, surface.tag};
  if (!surface.geometry) throw MeshError(id, "surface has no geometry");
  if (surface.loops.empty()) throw MeshError(id, "surface has no boundary");
  const SurfaceGeometry& g = *surface.geometry;
  const SurfaceInput in = collectInput(model, surface, mesh);
  const std::vector<Vec2> uv = parameters(g, mesh, in.nodes);
  const WorkFrame frame(g, boxCenter(uv));
  std::vector<Vec2> work;
  work.reserve(uv.size());
  for (Vec2 p : uv) work.push_back(frame.toWork(p));

  Triangulation2D tri = triangulateBoundary(in, work, id, mesh);
  std::vector<std::uint8_t> inside = classifyInside(tri);
  if (std::find(inside.begin(), inside.end(), 1) == inside.end())
    throw MeshError(id, "the boundary encloses no area");

  const SurfaceMetric metric(g, frame);
  const WorkPlaneSize field = [&](Vec2 work) {
    return rules.finish(fields->at(g.point(frame.toParam(work)), id));
  };
  const bool withField = fields && fields->hasBackground();
  setBoundarySizes(in, rules, mesh, tri);
  const std::uint32_t firstMovable =
      Triangulation2D::kFirstVertex + static_cast<std::uint32_t>(in.nodes.size());
  SurfaceInterior interior{tri, inside, firstMovable, smoothingPasses,
                           g.isPlane() ? nullptr : &metric, withField ? &field : nullptr};
  const PlanarMesh planar = algorithm.mesh(interior);

  EntityMesh& em = mesh.entity(id);
  em.nodes.clear();
  em.parametric.clear();
  em.blocks.clear();
  storeMesh(planar, in, frame, g, em, mesh);
}

}  // namespace geomesh
