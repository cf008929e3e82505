// meshSurface: the boundary's constrained triangulation, target sizes, then the 2D algorithm.
#include "mesh/surfaces/surface_mesher.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "mesh/surfaces/anisotropic_metric.h"
#include "mesh/surfaces/boundary_layer_2d.h"
#include "mesh/surfaces/constrained_delaunay.h"
#include "mesh/surfaces/landing_grid.h"
#include "mesh/curves/curve_mesher.h"
#include "mesh/core/mesh_error.h"
#include "mesh/surfaces/surface_metric.h"

namespace geomesh {
namespace {

double distance(Vec2 a, Vec2 b) { return std::hypot(a.u - b.u, a.v - b.v); }

// The points and constrained segments a surface's triangulation starts from, numbered
// locally. A point is a mesh node at a place of the parameter plane: a node on a seam has a
// point on each side, a pole one per piece of its segment.
struct SurfaceInput {
  std::vector<NodeIndex> nodes;          // the node of each point
  std::vector<std::optional<Vec2>> uv;   // its parameters, when the surface gave them
  std::vector<ConstrainedSegment> segments;
  std::vector<int> segmentCurve;  // tag of the curve each segment comes from
  std::unordered_map<NodeIndex, std::vector<std::uint32_t>> pointsOf;
  std::vector<double> givenSize;  // a boundary layer front's size at a point (0: none)
  std::vector<Vec2> seeds;  // free points around poles (parameters), numbered after the points
  double seedSize = 0;      // their target size
  double tolerance = 0;  // parameter distance under which two places of a node are one

  // The point of node n at `place`: an existing one of n at the same place (or any one of n
  // when either place is unknown), else a new one.
  std::uint32_t local(NodeIndex n, std::optional<Vec2> place = std::nullopt) {
    std::vector<std::uint32_t>& points = pointsOf[n];
    for (std::uint32_t k : points)
      if (!place || !uv[k] || distance(*place, *uv[k]) <= tolerance) return k;
    const auto k = static_cast<std::uint32_t>(nodes.size());
    nodes.push_back(n);
    uv.push_back(place);
    points.push_back(k);
    return k;
  }
  // Adds the chain's segments and returns its first and last points. `start` and `end`, when
  // given, are the points where it meets the previous and the next curve of its loop: there,
  // the curves' places in the parameter plane are one, even where their curves on the surface
  // differ by the CAD model's tolerance.
  std::pair<std::uint32_t, std::uint32_t> addChain(const std::vector<NodeIndex>& chain,
                                                   const std::vector<std::optional<Vec2>>& at,
                                                   int curve, EdgeKind kind,
                                                   std::optional<std::uint32_t> start = {},
                                                   std::optional<std::uint32_t> end = {}) {
    auto pointAt = [&](std::size_t k, std::optional<std::uint32_t> given) {
      return given && nodes[*given] == chain[k] ? *given : local(chain[k], at[k]);
    };
    const std::uint32_t first = pointAt(0, start);
    std::uint32_t previous = first;
    for (std::size_t k = 1; k < chain.size(); ++k) {
      const std::uint32_t next =
          pointAt(k, k + 1 == chain.size() ? end : std::optional<std::uint32_t>());
      segments.push_back({previous, next, kind});
      segmentCurve.push_back(curve);
      previous = next;
    }
    return {first, previous};
  }
};

// Where the surface puts the chain's nodes, when it knows the curve; unknown places otherwise.
std::vector<std::optional<Vec2>> chainPlaces(const Model& model, const Mesh& mesh,
                                             const SurfaceGeometry& g, int signedTag,
                                             std::size_t count) {
  std::vector<std::optional<Vec2>> at(count);
  const std::vector<double> ts = curveNodeParameters(model, mesh, signedTag);
  if (ts.size() != count || !g.curveParameters(signedTag, ts.front())) return at;
  for (std::size_t k = 0; k < count; ++k) at[k] = g.curveParameters(signedTag, ts[k]);
  return at;
}

bool isDegenerate(const Model& model, int signedTag) {
  const ModelCurve* curve = model.curve(std::abs(signedTag));
  return curve && curve->geometry && curve->geometry->isDegenerate();
}

// A curve of a loop as its nodes and their places; a pole's places are the ends of its segment.
struct LoopPiece {
  int curve;  // signed
  std::vector<NodeIndex> chain;
  std::vector<std::optional<Vec2>> at;
  bool pole;
};

LoopPiece loopPiece(const Model& model, const Mesh& mesh, const SurfaceGeometry& g, int curve) {
  LoopPiece piece{curve, curveNodeChain(model, mesh, curve), {}, false};
  piece.at = chainPlaces(model, mesh, g, curve, piece.chain.size());
  piece.pole = isDegenerate(model, curve) && piece.at.front() && piece.at.back();
  return piece;
}

// The mean length in space of the pieces' segments (poles have none).
double meanSegmentLength(const std::vector<std::vector<LoopPiece>>& loops, const Mesh& mesh) {
  double total = 0;
  int count = 0;
  for (const std::vector<LoopPiece>& loop : loops)
    for (const LoopPiece& piece : loop)
      for (std::size_t k = 0; k + 1 < piece.chain.size(); ++k) {
        const double length = distance(mesh.node(piece.chain[k]), mesh.node(piece.chain[k + 1]));
        if (length > 0) total += length, ++count;
      }
  return count > 0 ? total / count : 0;
}

// A ring of free points `size` away from a pole's segment, at least six per turn, so that
// the triangles around the pole each span a small part of the turn: without them a coarse
// mesh may close the turn with two triangles, flat in space (at a cone's apex).
void addPoleRing(SurfaceInput& in, const SurfaceGeometry& g, Vec2 a, Vec2 b, double size) {
  const Vec2 along{b.u - a.u, b.v - a.v};
  const double length = std::hypot(along.u, along.v);
  if (!(length > 0) || !(size > 0)) return;
  const Vec2 inward{-along.v / length, along.u / length};  // the domain lies left of its loops
  const SurfaceDerivatives d = g.firstDerivatives({0.5 * (a.u + b.u), 0.5 * (a.v + b.v)});
  const double speed = norm(inward.u * d.du + inward.v * d.dv);
  const ParamBox box = g.bounds();
  const double extent = std::abs(inward.u) * (box.u.max - box.u.min) +
                        std::abs(inward.v) * (box.v.max - box.v.min);
  if (!(speed > 0) || !std::isfinite(extent)) return;
  const double offset = std::min(size / speed, 0.25 * extent);
  auto ringPoint = [&](double f) {
    return Vec2{a.u + f * along.u + offset * inward.u, a.v + f * along.v + offset * inward.v};
  };
  constexpr int kSamples = 64;
  double ring = 0;
  for (int k = 0; k < kSamples; ++k)
    ring += distance(g.point(ringPoint(double(k) / kSamples)),
                     g.point(ringPoint(double(k + 1) / kSamples)));
  constexpr double kMinimum = 6, kMaximum = 10000;
  const int count = static_cast<int>(std::clamp(std::ceil(ring / size), kMinimum, kMaximum));
  for (int k = 0; k < count; ++k) in.seeds.push_back(ringPoint((k + 0.5) / count));
  in.seedSize = size;
}

// A degenerate curve (a pole) is a segment of the parameter plane: it gets copies of its node,
// fewer than its length at the parameter box centre would need at `size` (a quarter: more only
// make thinner triangles at the pole), and a ring of free points around it.
void expandPole(SurfaceInput& in, const SurfaceGeometry& g, LoopPiece& piece, double size) {
  const Vec2 a = *piece.at.front(), b = *piece.at.back();
  const ParamBox box = g.bounds();
  const SurfaceDerivatives d =
      g.firstDerivatives({0.5 * (box.u.min + box.u.max), 0.5 * (box.v.min + box.v.max)});
  const double length = norm((b.u - a.u) * d.du + (b.v - a.v) * d.dv);
  constexpr double kMaxCopies = 10000;
  const int pieces =
      size > 0 ? static_cast<int>(std::clamp(std::ceil(length / size / 4), 1.0, kMaxCopies)) : 1;
  piece.chain.assign(pieces + 1, piece.chain.front());
  piece.at.resize(pieces + 1);
  for (int k = 0; k <= pieces; ++k) {
    const double f = static_cast<double>(k) / pieces;
    piece.at[k] = Vec2{a.u + f * (b.u - a.u), a.v + f * (b.v - a.v)};
  }
  addPoleRing(in, g, a, b, size);
}

// Each loop closes on itself: each curve starts at the point where the previous one ends.
void addLoop(SurfaceInput& in, const std::vector<LoopPiece>& loop) {
  std::optional<std::uint32_t> first, previous;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const LoopPiece& piece = loop[k];
    const auto [start, end] =
        in.addChain(piece.chain, piece.at, std::abs(piece.curve), EdgeKind::Boundary, previous,
                    k + 1 == loop.size() ? first : std::nullopt);
    if (!first) first = start;
    previous = end;
  }
}

// Under this distance two nodes are at one place: a billionth of the boundary's extent, far
// below any element, far above rounding.
double coincidence(const BoundingBox& box) {
  return box.empty() ? 0 : 1e-9 * distance(box.min, box.max);
}

// An end of an embedded curve on another curve is only meshable when it is a point of that
// curve too (the curve must be split there): otherwise the two meshes would cross or overlap.
void requireSharedEnds(const SurfaceInput& in, const LandingGrid& grid, const ModelCurve& curve,
                       const LoopPiece& piece, EntityId id) {
  for (const auto& [point, node] : {std::pair{curve.startPoint, piece.chain.front()},
                                    std::pair{curve.endPoint, piece.chain.back()}}) {
    if (in.pointsOf.contains(node)) continue;  // a point the surface has already
    const LandingGrid::Landing landing = grid.find(node);
    if (landing.curve == 0 && !landing.node) continue;
    throw MeshError(id, "point " + std::to_string(point) + ", an end of embedded curve " +
                            std::to_string(curve.tag) + ", lies on " +
                            (landing.curve ? "curve " + std::to_string(landing.curve)
                                           : std::string("another embedded point")) +
                            " without being one of its points: split that curve at point " +
                            std::to_string(point));
  }
}

// Embedded curves, each checked against what was collected before it.
void addEmbeddedCurves(SurfaceInput& in, LandingGrid& grid, const Model& model,
                       const Mesh& mesh, const ModelSurface& surface) {
  for (int curve : surface.embeddedCurves) {
    const LoopPiece piece = loopPiece(model, mesh, *surface.geometry, curve);
    if (const ModelCurve* c = model.curve(curve))
      requireSharedEnds(in, grid, *c, piece, {2, surface.tag});
    in.addChain(piece.chain, piece.at, curve, EdgeKind::Embedded);
    for (std::size_t k = 0; k + 1 < piece.chain.size(); ++k)
      grid.addSegment(piece.chain[k], piece.chain[k + 1], curve);
  }
}

// Embedded points: one at the place of a node the surface has already (a boundary node, or a
// point embedded twice) is that node; one on a segment of a curve is rejected.
void addEmbeddedPoints(SurfaceInput& in, LandingGrid& grid, const Mesh& mesh,
                       const ModelSurface& surface) {
  for (int point : surface.embeddedPoints) {
    const NodeIndex node = pointNode(mesh, point);
    if (!in.pointsOf.contains(node)) {
      const LandingGrid::Landing landing = grid.find(node);
      if (landing.node) continue;
      if (landing.curve != 0)
        throw MeshError({2, surface.tag},
                        "embedded point " + std::to_string(point) + " lies on curve " +
                            std::to_string(landing.curve) + " between two of its nodes");
      grid.addPoint(node);
    }
    in.local(node);
  }
}

// The embedded curves and points, checked against the boundary and each other.
void addEmbedded(SurfaceInput& in, const Model& model, const Mesh& mesh,
                 const ModelSurface& surface, double segmentLength) {
  if (surface.embeddedCurves.empty() && surface.embeddedPoints.empty()) return;
  BoundingBox box;
  for (NodeIndex n : in.nodes) box.include(mesh.node(n));
  const double extent = box.empty() ? 0 : distance(box.min, box.max);
  LandingGrid grid(mesh, coincidence(box), std::max(segmentLength, extent / 256));
  for (std::size_t k = 0; k < in.segments.size(); ++k)
    grid.addSegment(in.nodes[in.segments[k].a], in.nodes[in.segments[k].b], in.segmentCurve[k]);
  addEmbeddedCurves(in, grid, model, mesh, surface);
  addEmbeddedPoints(in, grid, mesh, surface);
}

SurfaceInput collectInput(const Model& model, const ModelSurface& surface, const Mesh& mesh) {
  const SurfaceGeometry& g = *surface.geometry;
  SurfaceInput in;
  const ParamBox box = g.bounds();
  in.tolerance = 1e-6 * std::hypot(box.u.max - box.u.min, box.v.max - box.v.min);
  if (!std::isfinite(in.tolerance)) in.tolerance = 0;
  std::vector<std::vector<LoopPiece>> loops;
  for (const std::vector<int>& loop : surface.loops) {
    loops.emplace_back();
    for (int curve : loop) loops.back().push_back(loopPiece(model, mesh, g, curve));
  }
  const double size = meanSegmentLength(loops, mesh);
  for (std::vector<LoopPiece>& loop : loops)
    for (LoopPiece& piece : loop)
      if (piece.pole) expandPole(in, g, piece, size);
  for (const std::vector<LoopPiece>& loop : loops) addLoop(in, loop);
  addEmbedded(in, model, mesh, surface, size);
  return in;
}

// The input of the rest of a surface beyond its boundary layer: the layer's fronts instead of
// the boundary loops, each front node keeping the spacing of the wall below it.
SurfaceInput layerInput(const Model& model, const ModelSurface& surface, const Mesh& mesh,
                        const SurfaceLayer& layer) {
  SurfaceInput in;
  const ParamBox box = surface.geometry->bounds();
  in.tolerance = 1e-6 * std::hypot(box.u.max - box.u.min, box.v.max - box.v.min);
  if (!std::isfinite(in.tolerance)) in.tolerance = 0;
  double total = 0;
  std::size_t count = 0;
  for (std::size_t f = 0; f < layer.fronts.size(); ++f) {
    std::vector<NodeIndex> chain = layer.fronts[f];
    std::vector<std::optional<Vec2>> at(layer.frontParameters[f].begin(),
                                        layer.frontParameters[f].end());
    chain.push_back(chain.front());
    at.push_back(at.front());
    in.addChain(chain, at, 0, EdgeKind::Boundary);
    in.givenSize.resize(in.nodes.size(), 0.0);
    for (std::size_t k = 0; k < layer.fronts[f].size(); ++k) {
      in.givenSize[in.pointsOf[layer.fronts[f][k]].front()] = layer.frontSizes[f][k];
      total += layer.frontSizes[f][k], ++count;
    }
  }
  addEmbedded(in, model, mesh, surface, count ? total / count : 0);
  in.givenSize.resize(in.nodes.size(), 0.0);
  return in;
}

std::vector<Vec2> parameters(const SurfaceGeometry& g, const Mesh& mesh, const SurfaceInput& in) {
  std::vector<Vec2> uv;
  uv.reserve(in.nodes.size());
  for (std::size_t k = 0; k < in.nodes.size(); ++k)
    uv.push_back(in.uv[k] ? *in.uv[k] : g.project(mesh.node(in.nodes[k])));
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
    if (!(length > 0)) continue;  // a piece of a pole
    total[s.a] += length, total[s.b] += length;
    ++count[s.a], ++count[s.b];
  }
  const double fallback = rules.finish(rules.defaultSize);
  for (std::uint32_t k = 0; k < in.nodes.size(); ++k) {
    const NodeIndex n = in.nodes[k];
    if (k < in.givenSize.size() && in.givenSize[k] > 0)
      tri.setSize(k + first, in.givenSize[k]);
    else if (count[k] > 0)
      tri.setSize(k + first, total[k] / count[k]);
    else
      tri.setSize(k + first, mesh.nodeSize(n) > 0 ? mesh.nodeSize(n) : fallback);
  }
}

std::uint32_t firstSeed(const SurfaceInput& in) {
  return Triangulation2D::kFirstVertex + static_cast<std::uint32_t>(in.nodes.size());
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
  // A triangle with two corners at a pole has collapsed: it is left out.
  ElementBlock& triangles = em.block(ElementType::Triangle3);
  for (std::size_t t = 0; t + 2 < planar.triangles.size(); t += 3) {
    const NodeIndex a = globalOf[planar.triangles[t]], b = globalOf[planar.triangles[t + 1]],
                    c = globalOf[planar.triangles[t + 2]];
    if (a != b && b != c && c != a) triangles.nodes.insert(triangles.nodes.end(), {a, b, c});
  }
}

// The greatest curvature found on a grid over the parameter box and at the boundary's points:
// enough to tell whether sizes could outgrow a bend (see bendSize).
double sampledCurvature(const SurfaceGeometry& g, const std::vector<Vec2>& boundary) {
  const ParamBox box = g.bounds();
  constexpr int kSamples = 32;
  double worst = 0;
  for (Vec2 uv : boundary) worst = std::max(worst, surfaceCurvature(g, uv));
  if (!std::isfinite(box.u.max - box.u.min) || !std::isfinite(box.v.max - box.v.min))
    return worst;
  for (int i = 0; i <= kSamples; ++i)
    for (int j = 0; j <= kSamples; ++j) {
      const double fu = static_cast<double>(i) / kSamples, fv = static_cast<double>(j) / kSamples;
      worst = std::max(worst, surfaceCurvature(g, {box.u.min + fu * (box.u.max - box.u.min),
                                                   box.v.min + fv * (box.v.max - box.v.min)}));
    }
  return worst;
}

// The largest size the interior may take before a field or curvature bound applies: the
// boundary's sizes extend inwards, or sizeMax is used everywhere.
double largestInteriorSize(const Triangulation2D& tri, const SurfaceInput& in,
                           const SizeRules& rules) {
  if (!rules.extendFromBoundary) return rules.finish(rules.sizeMax);
  double largest = 0;
  for (std::uint32_t k = 0; k < in.nodes.size(); ++k)
    largest = std::max(largest, tri.size(k + Triangulation2D::kFirstVertex));
  return largest;
}

// The metric the anisotropic algorithm follows: the background's (SizeFields::metric, a 3D
// tensor restricted to the surface), its sizes clamped and scaled as Mesh.MeshSizeMin/Max and
// Mesh.MeshSizeFactor say, intersected with the curvature's isotropic bound when asked for.
Metric2 backgroundMetric(const SurfaceGeometry& g, const WorkFrame& frame,
                         const SurfaceMetric& lengthsOnSurface, EntityId id,
                         const SizeRules& rules, const SizeFields* fields, bool withCurvature,
                         const AnisotropicSettings& settings, Vec2 work) {
  const Vec2 uv = frame.toParam(work);
  const auto [t1, t2] = lengthsOnSurface.tangents(work);
  const Metric2 lengths{dot(t1, t1), dot(t1, t2), dot(t2, t2)};
  if (!isPositiveDefinite(lengths)) return {};  // a pole: the other algorithms' fallback too
  const MetricFrame surface(lengths);
  Metric2 m = isotropicMetric(rules.finish(rules.sizeMax));
  if (fields)
    if (const auto m3 = fields->metric(g.point(uv), id)) {
      const Metric2 restricted = inFrame(restrictMetric(*m3, t1, t2), surface);
      if (isPositiveDefinite(restricted)) m = restricted;
    }
  m = mapSizes(m, [&](double h) { return rules.finish(h); }, settings.anisoMax);
  if (withCurvature)
    m = intersect(m, isotropicMetric(rules.finish(rules.curvatureSize(surfaceCurvature(g, uv)))));
  return outOfFrame(m, surface);
}

// The boundary layer's elements, first in their blocks (EntityMesh::layer).
void addLayerElements(const SurfaceLayer& layer, EntityMesh& em) {
  if (!layer.triangles.empty()) {
    ElementBlock& triangles = em.block(ElementType::Triangle3);
    triangles.nodes.insert(triangles.nodes.end(), layer.triangles.begin(), layer.triangles.end());
  }
  if (!layer.quadrangles.empty()) {
    ElementBlock& quadrangles = em.block(ElementType::Quad4);
    quadrangles.nodes.insert(quadrangles.nodes.end(), layer.quadrangles.begin(),
                             layer.quadrangles.end());
  }
}

// Elements of a boundary layer's fan at a corner: Mesh.BoundaryLayerFanElements' default.
constexpr int kFanElements = 5;

// Meshes the surface, with the boundary layers of `fields`; `layered` tells whether a layer
// was built.
void meshSurfaceOnce(const Model& model, const ModelSurface& surface, const SizeRules& rules,
                     int smoothingPasses, Mesh& mesh, const SizeFields* fields,
                     const SurfaceAlgorithm& algorithm, const AnisotropicSettings& anisotropy,
                     bool& layered) {
  const EntityId id{2, surface.tag};
  if (!surface.geometry) throw MeshError(id, "surface has no geometry");
  if (surface.loops.empty()) throw MeshError(id, "surface has no boundary");
  const SurfaceGeometry& g = *surface.geometry;
  EntityMesh& em = mesh.entity(id);
  std::optional<SurfaceLayer> layer;
  if (fields)
    if (const auto layers = fields->boundaryLayers(); !layers.empty()) {
      em.nodes.clear();
      em.parametric.clear();
      layer = buildSurfaceLayer(model, surface, layers, kFanElements, *fields, mesh, em);
    }
  layered = layer.has_value();
  const SurfaceInput in =
      layer ? layerInput(model, surface, mesh, *layer) : collectInput(model, surface, mesh);
  const std::vector<Vec2> uv = parameters(g, mesh, in);
  const WorkFrame frame(g, boxCenter(uv));
  std::vector<Vec2> work;
  work.reserve(uv.size() + in.seeds.size());
  for (Vec2 p : uv) work.push_back(frame.toWork(p));
  for (Vec2 p : in.seeds) work.push_back(frame.toWork(p));

  Triangulation2D tri = triangulateBoundary(in, work, id, mesh);
  std::vector<std::uint8_t> inside = classifyInside(tri);
  if (std::find(inside.begin(), inside.end(), 1) == inside.end())
    throw MeshError(id, "the boundary encloses no area");

  const SurfaceMetric metric(g, frame);
  setBoundarySizes(in, rules, mesh, tri);
  // Bounds on the interior's size besides the boundary's: the background field, with
  // Mesh.MeshSizeFromCurvature the surface's own curvature, and always a few elements per
  // turn of a bend tighter than the sizes (checked on samples first: on most surfaces the
  // sizes are far below every bend, and the bound costs nothing).
  const bool withField = fields && fields->hasBackground();
  const bool withCurvature = rules.elementsPerTwoPi > 0 && !g.isPlane();
  const double largest = std::max(largestInteriorSize(tri, in, rules),
                                  withField ? rules.finish(rules.sizeMax) : 0.0);
  // Not on a surface with a pole: towards a cone's apex the bend tightens without end, and the
  // ring of points around the pole already keeps the triangles there from wrapping round it.
  const bool withBend = !g.isPlane() && !hasPole(model, surface) &&
                        sizesOutgrowBend(sampledCurvature(g, uv), largest);
  const WorkPlaneSize field = [&](Vec2 work) {
    const Vec2 uv = frame.toParam(work);
    double size = withField ? fields->at(g.point(uv), id) : rules.sizeMax;
    if (withCurvature) size = std::min(size, rules.curvatureSize(surfaceCurvature(g, uv)));
    return rules.finish(size);
  };
  // The bend bound holds even below Mesh.MeshSizeMin: a valid mesh comes first.
  const WorkPlaneSize bend = [&](Vec2 work) {
    return bendSize(surfaceCurvature(g, frame.toParam(work)), largest);
  };
  const WorkPlaneSize both = [&](Vec2 work) {
    return withField || withCurvature ? std::min(field(work), bend(work)) : bend(work);
  };
  for (std::size_t k = 0; k < in.seeds.size(); ++k)
    tri.setSize(firstSeed(in) + static_cast<std::uint32_t>(k), in.seedSize);
  // The rings around poles stay where they are put: smoothing in the surface's metric, which
  // vanishes along a pole, would slide them round the turn.
  const std::uint32_t firstMovable =
      firstSeed(in) + static_cast<std::uint32_t>(in.seeds.size());
  const WorkPlaneMetric anisotropic = [&](Vec2 work) {
    return backgroundMetric(g, frame, metric, id, rules, withField ? fields : nullptr,
                            withCurvature, anisotropy, work);
  };
  SurfaceInterior interior{tri,
                           inside,
                           firstMovable,
                           smoothingPasses,
                           g.isPlane() ? nullptr : &metric,
                           withField || withCurvature ? &field : nullptr,
                           withBend ? &bend : nullptr,
                           withBend ? &both : (withField || withCurvature ? &field : nullptr),
                           withField || withCurvature ? &anisotropic : nullptr,
                           anisotropy};
  const PlanarMesh planar = algorithm.mesh(interior);

  if (!layer) {
    em.nodes.clear();
    em.parametric.clear();
  }
  em.blocks.clear();
  em.layer.reset();
  if (layer) {
    em.layer = EntityMesh::LayerPart{em.nodes.size(), layer->triangles.size() / 3,
                                     layer->quadrangles.size() / 4};
    addLayerElements(*layer, em);
  }
  storeMesh(planar, in, frame, g, em, mesh);
}

}  // namespace

void meshSurface(const Model& model, const ModelSurface& surface, const SizeRules& rules,
                 int smoothingPasses, Mesh& mesh, const SizeFields* fields,
                 const SurfaceAlgorithm& algorithm, const AnisotropicSettings& anisotropy) {
  bool layered = false;
  try {
    meshSurfaceOnce(model, surface, rules, smoothingPasses, mesh, fields, algorithm, anisotropy,
                    layered);
  } catch (const MeshError& e) {
    if (!layered) throw;
    // The layer's front crosses itself or the boundary somewhere the shortening did not
    // see. A mesh without the layer asked for is no answer: the surface is named instead.
    const std::string prefix = "cannot mesh " + entityName(e.entity) + ": ";
    const std::string what = e.what();
    throw MeshError({2, surface.tag},
                    "the rest of the mesh cannot be joined to its boundary layer (" +
                        (what.starts_with(prefix) ? what.substr(prefix.size()) : what) +
                        "); a thinner layer (Thickness) or finer sizes along its walls may fit");
  }
}

}  // namespace geomesh
