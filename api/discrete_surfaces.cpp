// Session: ClassifySurfaces, CreateTopology and CreateGeometry on merged triangulations.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <stdexcept>

#include "api/discrete_model.h"
#include "api/session.h"
#include "mesh/discrete/classification.h"
#include "mesh/discrete/discrete_surface_geometry.h"
#include "mesh/discrete/parametrization.h"
#include "mesh/discrete/surface_curvature.h"

namespace geomesh {

namespace {

constexpr int kMaxSplitRounds = 12;

// The triangles of the discrete surfaces `surfaces` of the merged mesh: triangles as they
// are, quadrangles split in two, high-order elements by their corners.
DiscreteModel gatherTriangles(const Mesh& mesh, const std::set<int>& surfaces) {
  DiscreteModel d;
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> local(mesh.nodeCount(), kNone);
  auto vertex = [&](NodeIndex n) {
    if (local[n] == kNone) {
      local[n] = static_cast<std::uint32_t>(d.triangulation.points.size());
      d.triangulation.points.push_back(mesh.node(n));
    }
    return local[n];
  };
  for (int tag : surfaces) {
    const EntityMesh* em = mesh.find({2, tag});
    if (!em) continue;
    for (const ElementBlock& block : em->blocks) {
      if (dimension(block.type) != 2) continue;
      const int corners = vertexCount(block.type);
      for (std::size_t e = 0; e < block.size(); ++e) {
        const auto nodes = block.element(e);
        for (int k = 1; k + 1 < corners; ++k) {
          d.triangulation.triangles.push_back(
              {vertex(nodes[0]), vertex(nodes[static_cast<std::size_t>(k)]),
               vertex(nodes[static_cast<std::size_t>(k + 1)])});
          d.surfaceOf.push_back(tag);
        }
      }
    }
  }
  return d;
}

// A loop of signed curves as a closed cycle of vertices (the first not repeated).
std::vector<std::uint32_t> loopVertices(const DiscreteModel& d, const std::vector<int>& loop) {
  std::vector<std::uint32_t> cycle;
  for (int c : loop) {
    std::vector<std::uint32_t> chain = d.curves.at(std::abs(c));
    if (c < 0) std::reverse(chain.begin(), chain.end());
    cycle.insert(cycle.end(), chain.begin(), chain.end() - 1);
  }
  return cycle;
}

// The triangles of each surface, ascending.
std::map<int, std::vector<std::uint32_t>> trianglesBySurface(const DiscreteModel& d) {
  std::map<int, std::vector<std::uint32_t>> triangles;
  for (std::uint32_t t = 0; t < d.surfaceOf.size(); ++t) triangles[d.surfaceOf[t]].push_back(t);
  return triangles;
}

// How curve `chain` runs through the map: the polyline's parameter (its length run, as a
// fraction of the whole, as PolylineGeometry has it) and the uv at each vertex.
CurveTrace curveTrace(const Triangulation& t, const std::vector<std::uint32_t>& chain,
                      const std::map<std::uint32_t, std::uint32_t>& localOf, const PatchMap& map) {
  CurveTrace trace;
  double run = 0;
  for (std::size_t k = 0; k < chain.size(); ++k) {
    if (k > 0) run += distance(t.points[chain[k - 1]], t.points[chain[k]]);
    trace.t.push_back(run);
    trace.uv.push_back(map.uv[localOf.at(chain[k])]);
  }
  for (double& s : trace.t) s = run > 0 ? s / run : 0;
  return trace;
}

std::shared_ptr<const SurfaceGeometry> surfaceGeometry(const DiscreteModel& d, int surface,
                                                       PatchMap map) {
  const Triangulation& t = d.triangulation;
  std::map<std::uint32_t, std::uint32_t> localOf;
  Triangulation patch;
  for (std::uint32_t k = 0; k < map.vertices.size(); ++k) {
    localOf.emplace(map.vertices[k], k);
    patch.points.push_back(t.points[map.vertices[k]]);
  }
  patch.triangles = map.triangles;
  std::map<int, CurveTrace> traces;
  for (const std::vector<int>& loop : d.loops.at(surface))
    for (int c : loop)
      traces.emplace(std::abs(c), curveTrace(t, d.curves.at(std::abs(c)), localOf, map));
  std::vector<double> curvature;
  if (!map.planar) curvature = vertexCurvatures(patch).maxAbs;
  return std::make_shared<DiscreteSurfaceGeometry>(std::move(patch.points), std::move(map),
                                                   std::move(traces), std::move(curvature));
}

std::string formatNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.16g", x);
  return text;
}

}  // namespace

DiscreteModel& Session::discreteModel() {
  if (discrete_) return *discrete_;
  adoptSurfaceMeshFile();
  std::set<int> surfaces;
  for (int tag : factories_.tags(2))
    if (factories_.discrete().isDiscrete({2, tag})) surfaces.insert(tag);
  discrete_ = std::make_unique<DiscreteModel>(gatherTriangles(discreteMesh_, surfaces));
  DiscreteModel& d = *discrete_;
  d.file = discreteFile_;
  for (int tag : surfaces) d.loops[tag] = {};
  Triangulation& t = d.triangulation;
  BoundingBox box;
  for (const Vec3& p : t.points) box.include(p);
  const double size = box.empty() ? 0.0 : distance(box.min, box.max);
  const std::size_t before = t.triangles.size();
  const std::size_t welded = mergeDuplicateVertices(t, 1e-10 * size, &d.surfaceOf);
  if (t.triangles.size() != before)
    log_.warning("Merged triangulation: " + std::to_string(before - t.triangles.size()) +
                 " degenerate or repeated triangles removed");
  if (welded > 0) log_.info("Merged triangulation: " + std::to_string(welded) + " vertices welded");
  if (const std::size_t flipped = orientConsistently(t); flipped > 0)
    log_.warning("Merged triangulation: " + std::to_string(flipped) +
                 " triangles turned to agree with their neighbours");
  if (const TriangleAdjacency a = triangleAdjacency(t.triangles); !a.nonManifoldEdges.empty()) {
    const auto [p, q] = a.nonManifoldEdges.front();
    const Vec3 x = t.points[p], y = t.points[q];
    log_.warning("Merged triangulation: " + std::to_string(a.nonManifoldEdges.size()) +
                 " edges are shared by more than two triangles, the first from (" +
                 formatNumber(x.x) + ", " + formatNumber(x.y) + ", " + formatNumber(x.z) +
                 ") to (" + formatNumber(y.x) + ", " + formatNumber(y.y) + ", " +
                 formatNumber(y.z) + ")");
  }
  return d;
}

// Replaces the factory's discrete points, curves and surfaces by those of `topology` (each
// patch a surface), numbered on from the largest tags in use, and the merged mesh by the
// triangulation's, so that meshing copies what CreateGeometry leaves discrete.
void Session::replaceDiscreteTopology(const DiscreteTopology& topology) {
  DiscreteModel& d = *discrete_;
  const Triangulation& t = d.triangulation;
  DiscreteEntities& entities = factories_.discrete();
  GeometryFactory& builtIn = factories_.builtIn();
  const int firstPoint = builtIn.maxTag(0) + 1, firstCurve = builtIn.maxTag(1) + 1;
  const int firstSurface = builtIn.maxTag(2) + 1;
  std::vector<EntityId> old;
  for (const auto& [tag, loops] : d.loops) old.push_back({2, tag});
  for (const auto& [tag, chain] : d.curves) old.push_back({1, tag});
  for (const auto& [tag, vertex] : d.points) old.push_back({0, tag});
  builtIn.remove(old, false);
  d.loops.clear();
  d.curves.clear();
  d.points.clear();
  std::map<std::uint32_t, int> pointAt;
  for (std::size_t k = 0; k < topology.points.size(); ++k) {
    const int tag = firstPoint + static_cast<int>(k);
    entities.addDiscretePoint(tag, t.points[topology.points[k]]);
    d.points[tag] = topology.points[k];
    pointAt[topology.points[k]] = tag;
  }
  for (std::size_t k = 0; k < topology.curves.size(); ++k) {
    const std::vector<std::uint32_t>& chain = topology.curves[k].vertices;
    std::vector<Vec3> trace;
    for (std::uint32_t v : chain) trace.push_back(t.points[v]);
    const int tag = firstCurve + static_cast<int>(k);
    entities.addDiscreteCurve(tag, pointAt.at(chain.front()), pointAt.at(chain.back()),
                              std::move(trace));
    d.curves[tag] = chain;
  }
  discreteSurfaces_.clear();
  for (std::size_t k = 0; k < topology.patches.size(); ++k) {
    const DiscreteTopology::Patch& patch = topology.patches[k];
    const int tag = firstSurface + static_cast<int>(k);
    std::vector<std::vector<int>> loops;
    for (const std::vector<int>& loop : patch.loops) {
      std::vector<int>& signedTags = loops.emplace_back();
      for (int c : loop) signedTags.push_back((c > 0 ? 1 : -1) * (firstCurve + std::abs(c) - 1));
    }
    BoundingBox box;
    for (std::uint32_t tri : patch.triangles) {
      d.surfaceOf[tri] = tag;
      for (std::uint32_t v : t.triangles[tri]) box.include(t.points[v]);
    }
    entities.addDiscreteSurface(tag, box, d.file, loops);
    d.loops[tag] = std::move(loops);
    discreteSurfaces_.insert(tag);
  }
  rebuildDiscreteMesh();
  log_.info("Found " + std::to_string(topology.patches.size()) + " surfaces, " +
            std::to_string(topology.curves.size()) + " curves and " +
            std::to_string(topology.points.size()) + " points on the merged triangles");
}

void Session::rebuildDiscreteMesh() {
  const DiscreteModel& d = *discrete_;
  discreteMesh_ = Mesh();
  for (const Vec3& p : d.triangulation.points) discreteMesh_.addNode(p);
  for (const auto& [tag, vertex] : d.points)
    discreteMesh_.entity({0, tag}).block(ElementType::Point1).nodes.push_back(vertex);
  for (const auto& [tag, chain] : d.curves) {
    ElementBlock& lines = discreteMesh_.entity({1, tag}).block(ElementType::Line2);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k)
      lines.nodes.insert(lines.nodes.end(), {chain[k], chain[k + 1]});
  }
  for (std::uint32_t tri = 0; tri < d.triangulation.triangles.size(); ++tri) {
    const TriangleVertices& v = d.triangulation.triangles[tri];
    ElementBlock& block = discreteMesh_.entity({2, d.surfaceOf[tri]}).block(ElementType::Triangle3);
    block.nodes.insert(block.nodes.end(), v.begin(), v.end());
  }
}

void Session::classifySurfaces(double angle, bool includeBoundary, bool forReparametrization,
                               double curveAngle) {
  DiscreteModel& d = discreteModel();
  if (d.triangulation.triangles.empty())
    throw std::runtime_error(
        "ClassifySurfaces: there are no merged triangles to classify (merge a surface mesh "
        "first: STL, PLY, OFF, MSH, Medit or VTK)");
  ClassifyOptions options;
  options.angle = angle;
  options.includeBoundary = includeBoundary;
  options.forReparametrization = forReparametrization;
  options.curveAngle = curveAngle;
  d.curveAngle = curveAngle;
  const std::vector<int> labels = classifyByAngle(d.triangulation, d.surfaceOf, options);
  replaceDiscreteTopology(buildTopology(d.triangulation, labels, curveAngle));
  factories_.discrete().noteDiscreteStatement(
      "ClassifySurfaces{" + formatNumber(angle) + ", " + std::to_string(int(includeBoundary)) +
      ", " + std::to_string(int(forReparametrization)) + ", " + formatNumber(curveAngle) + "};");
}

void Session::createTopology() {
  DiscreteModel& d = discreteModel();
  if (d.triangulation.triangles.empty())
    throw std::runtime_error("CreateTopology: there are no merged triangles");
  replaceDiscreteTopology(buildTopology(d.triangulation, d.surfaceOf, d.curveAngle));
  factories_.discrete().noteDiscreteStatement("CreateTopology;");
}

// Maps every discrete surface to the plane. A surface that cannot be mapped (closed, with a
// handle, folded or too distorted) is split in two and the topology found again, until every
// one maps; then curves and surfaces get their geometry.
void Session::createGeometry() {
  DiscreteModel& d = discreteModel();
  if (d.triangulation.triangles.empty())
    throw std::runtime_error("CreateGeometry: there are no merged triangles");
  if (d.curves.empty() && d.points.empty())
    replaceDiscreteTopology(buildTopology(d.triangulation, d.surfaceOf, d.curveAngle));
  for (int round = 0;; ++round) {
    std::map<int, PatchMap> maps;
    std::vector<int> labels = d.surfaceOf;
    int next = *std::max_element(labels.begin(), labels.end()) + 1;
    bool split = false;
    const std::map<int, std::vector<std::uint32_t>> bySurface = trianglesBySurface(d);
    for (const auto& [tag, loops] : d.loops) {
      const auto found = bySurface.find(tag);
      const std::vector<std::uint32_t> triangles =
          found == bySurface.end() ? std::vector<std::uint32_t>{} : found->second;
      std::vector<std::vector<std::uint32_t>> cycles;
      for (const std::vector<int>& loop : loops) cycles.push_back(loopVertices(d, loop));
      ParametrizationResult result = parametrizePatch(d.triangulation, triangles, cycles);
      if (result.map) {
        if (result.map->planar)
          log_.info("Discrete surface " + std::to_string(tag) + " is plane: mapped by projection");
        maps.emplace(tag, std::move(*result.map));
        continue;
      }
      if (round == kMaxSplitRounds || triangles.size() < 2)
        throw std::runtime_error("CreateGeometry: discrete surface " + std::to_string(tag) +
                                 " cannot be mapped to the plane: " + result.failure);
      log_.info("Discrete surface " + std::to_string(tag) + " cannot be mapped to the plane (" +
                result.failure + "): split in two");
      const auto halves = splitPatch(d.triangulation, triangles);
      for (std::uint32_t tri : halves[1]) labels[tri] = next;
      ++next;
      split = true;
    }
    if (split) {
      replaceDiscreteTopology(buildTopology(d.triangulation, labels, d.curveAngle));
      continue;
    }
    DiscreteEntities& entities = factories_.discrete();
    for (auto& [tag, map] : maps)
      entities.setDiscreteSurfaceGeometry(tag, surfaceGeometry(d, tag, std::move(map)));
    for (const auto& [tag, chain] : d.curves) entities.setDiscreteCurveGeometry(tag);
    break;
  }
  factories_.discrete().noteDiscreteStatement("CreateGeometry;");
}

}  // namespace geomesh
