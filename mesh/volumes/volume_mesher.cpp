// meshVolume: the complex checked, its tetrahedra recovered, refined to sizes and improved.
#include "mesh/volumes/volume_mesher.h"

#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "mesh/core/mesh_error.h"
#include "mesh/core/predicates.h"
#include "mesh/structured/extrusion_mesher.h"
#include "mesh/volumes/abort_trap.h"
#include "mesh/volumes/boundary_delaunay.h"
#include "mesh/volumes/delaunay_tets.h"
#include "mesh/volumes/embedded_conformity.h"
#include "mesh/volumes/plc_containment.h"
#include "mesh/volumes/plc_intersections.h"
#include "mesh/volumes/pyramid_bases.h"
#include "mesh/volumes/tet_optimizer.h"
#include "mesh/volumes/tet_refinement.h"
#include "mesh/volumes/tet_smoothing.h"
#include "mesh/volumes/volume_estimate.h"
#include "mesh/volumes/volume_plc.h"

namespace geomesh {

namespace {

double signedTetVolume(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return dot(cross(b - a, c - a), d - a) / 6;
}

// Orients the triangles [first, last) consistently (each edge traversed once each way), by a
// walk across shared edges, then outward (positive enclosed volume).
void orientShell(std::vector<PlcTriangle>& tris, std::size_t first, std::size_t last,
                 const std::vector<Vec3>& xyz) {
  std::map<std::pair<int, int>, std::vector<std::size_t>> byEdge;
  for (std::size_t t = first; t < last; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = tris[t][k], b = tris[t][(k + 1) % 3];
      byEdge[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  auto runsForward = [&](std::size_t t, int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (tris[t][k] == a && tris[t][(k + 1) % 3] == b) return true;
    return false;
  };
  std::vector<char> seen(last - first, 0);
  for (std::size_t seed = first; seed < last; ++seed) {
    if (seen[seed - first]) continue;
    seen[seed - first] = 1;
    std::vector<std::size_t> stack{seed};
    while (!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int a = tris[t][k], b = tris[t][(k + 1) % 3];
        const auto& users = byEdge[{std::min(a, b), std::max(a, b)}];
        if (users.size() != 2) continue;  // boundary or non-manifold edge: no constraint
        const std::size_t n = users[0] == t ? users[1] : users[0];
        if (seen[n - first]) continue;
        seen[n - first] = 1;
        if (runsForward(n, a, b)) std::swap(tris[n][0], tris[n][1]);
        stack.push_back(n);
      }
    }
  }
  double volume = 0;
  const Vec3 origin = xyz[tris[first][0]];
  for (std::size_t t = first; t < last; ++t)
    volume += signedTetVolume(origin, xyz[tris[t][0]], xyz[tris[t][1]], xyz[tris[t][2]]);
  if (volume < 0)
    for (std::size_t t = first; t < last; ++t) std::swap(tris[t][0], tris[t][1]);
}

// Whether the triangles [first, last) close a region: each of their edges is on two of them.
bool isClosedShell(const std::vector<PlcTriangle>& tris, std::size_t first, std::size_t last) {
  std::map<std::pair<int, int>, int> uses;
  for (std::size_t t = first; t < last; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = tris[t][k], b = tris[t][(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  for (const auto& [edge, count] : uses)
    if (count != 2) return false;
  return true;
}

// A point inside an inner shell (a hole of the volume), just behind its largest triangle: the
// shell must be oriented outward.
Vec3 pointInsideShell(const std::vector<PlcTriangle>& tris, std::size_t first, std::size_t last,
                      const std::vector<Vec3>& xyz) {
  std::size_t best = first;
  double bestArea = -1;
  for (std::size_t t = first; t < last; ++t) {
    const double area =
        norm(cross(xyz[tris[t][1]] - xyz[tris[t][0]], xyz[tris[t][2]] - xyz[tris[t][0]]));
    if (area > bestArea) {
      bestArea = area;
      best = t;
    }
  }
  const Vec3 a = xyz[tris[best][0]], b = xyz[tris[best][1]], c = xyz[tris[best][2]];
  const Vec3 normal = normalized(cross(b - a, c - a));
  return (a + b + c) / 3 - 1e-3 * std::sqrt(bestArea) * normal;
}

// TetGen's input, pointing into arrays owned here: the triangles as facets (those of embedded
// surfaces are facets inside the domain), the segments of embedded curves as edges, which
// TetGen keeps as segments with -p, and every node, isolated ones included, as a point.
// tetgenio frees its arrays with delete[] on destruction, so the borrowed pointers are cleared
// first.
class TetgenInput {
 public:
  TetgenInput(const VolumePlc& plc, const std::vector<Vec3>& xyz,
              const std::vector<Vec3>& holes);
  ~TetgenInput() { release(); }
  TetgenInput(const TetgenInput&) = delete;
  TetgenInput& operator=(const TetgenInput&) = delete;
  tetgenio& io() { return io_; }

 private:
  void release();

  std::vector<double> points_, holes_;
  std::vector<int> corners_, edges_;
  std::vector<tetgenio::polygon> polygons_;
  std::vector<tetgenio::facet> facets_;
  tetgenio io_;
};

TetgenInput::TetgenInput(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                         const std::vector<Vec3>& holes) {
  for (Vec3 p : xyz) points_.insert(points_.end(), {p.x, p.y, p.z});
  for (Vec3 h : holes) holes_.insert(holes_.end(), {h.x, h.y, h.z});
  for (const PlcTriangle& t : plc.triangles) corners_.insert(corners_.end(), t.begin(), t.end());
  for (const PlcSegment& s : plc.segments) edges_.insert(edges_.end(), s.begin(), s.end());
  polygons_.resize(plc.triangles.size());
  facets_.resize(plc.triangles.size());
  for (std::size_t i = 0; i < plc.triangles.size(); ++i) {
    polygons_[i] = {corners_.data() + 3 * i, 3};
    facets_[i] = {&polygons_[i], 1, nullptr, 0};
  }
  io_.firstnumber = 0;
  io_.numberofpoints = static_cast<int>(xyz.size());
  io_.pointlist = points_.data();
  io_.numberoffacets = static_cast<int>(facets_.size());
  io_.facetlist = facets_.data();
  io_.numberofholes = static_cast<int>(holes.size());
  io_.holelist = holes_.empty() ? nullptr : holes_.data();
  io_.numberofedges = static_cast<int>(plc.segments.size());
  io_.edgelist = edges_.empty() ? nullptr : edges_.data();
}

void TetgenInput::release() {
  io_.pointlist = nullptr;
  io_.facetlist = nullptr;
  io_.numberoffacets = 0;
  io_.holelist = nullptr;
  io_.edgelist = nullptr;
  io_.numberofedges = 0;
}

std::string tetgenFailure(int code) {
  switch (code) {
    case 1: return "TetGen ran out of memory";
    case 3: return "its boundary surfaces intersect each other";
    case 4: return "its boundary has a feature too small for TetGen's tolerance";
    case 5: return "two of its boundary facets are too close to each other";
    case 10: return "TetGen rejected its boundary as invalid input";
    default: return "TetGen failed with an internal error (code " + std::to_string(code) + ")";
  }
}

// Whether TetGen ran to its end; false when it aborted on a failed assertion, which TetGen 1.5
// does on some exactly degenerate inputs (many cospherical and coplanar nodes, as a prism whose
// top is the translated copy of its bottom), depending on the order of the points.
bool recoverBoundary(const ModelVolume& volume, TetgenInput& input, tetgenio& output) {
  // p: boundary given as facets, recovered in the tetrahedralization of its nodes; Y: no node
  // added on it; z: zero-based numbering; Q: quiet. The interior is refined afterwards
  // (refineToSizes).
  char switches[] = "pYzQ";
  // TetGen and the abort trap around it (a signal handler, stderr redirected) are not made for
  // several threads: one volume at a time.
  static std::mutex oneAtATime;
  const std::lock_guard<std::mutex> lock(oneAtATime);
  try {
    return runTrappingAbort([&] { tetrahedralize(switches, &input.io(), &output); });
  } catch (int code) {
    throw MeshError({3, volume.tag}, tetgenFailure(code));
  }
}

// The recovered tetrahedra as the kernel's arrays, positively oriented, with the triangles of
// the embedded surfaces kept and the segments of the embedded curves too; the sizes at TetGen's
// own interior points (rare, where recovery needed them) from the boundary nodes around them.
DelaunayTets kernelMesh(const VolumePlc& plc, const tetgenio& out, std::vector<double>& sizes) {
  std::vector<Vec3> points;
  for (int i = 0; i < out.numberofpoints; ++i)
    points.push_back({out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]});
  std::vector<std::uint32_t> tets(out.tetrahedronlist,
                                  out.tetrahedronlist + 4 * std::size_t(out.numberoftetrahedra));
  for (std::size_t t = 0; t < tets.size(); t += 4)
    if (orient3d(points[tets[t]], points[tets[t + 1]], points[tets[t + 2]], points[tets[t + 3]]) <
        0)
      std::swap(tets[t], tets[t + 1]);
  const std::size_t known = plc.nodes.size();
  std::vector<double> sum(points.size(), 0), count(points.size(), 0);
  for (std::size_t t = 0; t < tets.size(); t += 4)
    for (int i = 0; i < 4; ++i)
      if (tets[t + i] >= known)
        for (int j = 0; j < 4; ++j)
          if (tets[t + j] < known) {
            sum[tets[t + i]] += sizes[tets[t + j]];
            ++count[tets[t + i]];
          }
  double largest = 0;
  for (double h : sizes) largest = std::max(largest, h);
  for (std::size_t i = known; i < points.size(); ++i)
    sizes.push_back(count[i] > 0 ? sum[i] / count[i] : largest);
  return complexTetrahedra(plc, std::move(points), std::move(tets));
}

// The tetrahedra of the complex's nodes with its triangles and segments as faces and edges:
// the kernel's own Delaunay tetrahedralization when it holds them all, else TetGen's recovery
// (tried in up to three orders of the nodes). `sizes` receives the size at each vertex.
DelaunayTets recoverTetrahedra(const ModelVolume& volume, VolumePlc& plc, std::vector<Vec3>& xyz,
                               const std::vector<Vec3>& holes, std::vector<double>& plcSizes,
                               std::vector<double>& sizes) {
  if (std::optional<DelaunayTets> tets = boundaryDelaunay(plc, xyz, holes)) {
    sizes = plcSizes;
    return std::move(*tets);
  }
  constexpr int kOrders = 3;
  for (int attempt = 0; attempt < kOrders; ++attempt) {
    if (attempt > 0) renumberPlc(plc, xyz, plcSizes, plc.nodes.size() / (attempt + 1) + 1);
    TetgenInput input(plc, xyz, holes);
    tetgenio output;
    if (recoverBoundary(volume, input, output)) {
      sizes = plcSizes;
      return kernelMesh(plc, output, sizes);
    }
  }
  throw MeshError({3, volume.tag}, "TetGen failed an internal check on its boundary mesh in " +
                                       std::to_string(kOrders) +
                                       " orders of its nodes (a degenerate configuration)");
}

// Improves the tetrahedra (4 indices into `points` each), moving only the points numbered
// firstInterior or more, keeping the complex's triangles and segments. Without Mesh.Optimize
// only nearly flat ones are repaired (they would not pass the mesh check); with it, every one
// below the threshold is improved.
void optimizeTetrahedra(const VolumePlc& plc, const MeshOptions& options,
                        std::uint32_t firstInterior, std::vector<Vec3>& points,
                        std::vector<std::uint32_t>& tets) {
  std::vector<char> movable(points.size(), 0);
  std::fill(movable.begin() + firstInterior, movable.end(), 1);
  const double threshold =
      options.optimize ? std::max(options.optimizeThreshold, kOptimizeBelowAtLeast) : kFlatBelow;
  optimizeTetrahedra(points, std::move(movable), tets, threshold, plcTriangles(plc),
                     plcSegments(plc));
}

// Adds the volume's new points (those after the complex's nodes) to the mesh, and its
// tetrahedra (4 indices into `points` each).
void appendTetrahedra(const ModelVolume& volume, const VolumePlc& plc,
                      const std::vector<Vec3>& points, const std::vector<std::uint32_t>& tets,
                      Mesh& mesh) {
  const EntityId id{3, volume.tag};
  if (tets.empty()) throw MeshError(id, "the volume mesher made no tetrahedra");
  EntityMesh& em = mesh.entity(id);
  std::vector<NodeIndex> global(plc.nodes);
  for (std::size_t i = plc.nodes.size(); i < points.size(); ++i) {
    global.push_back(mesh.addNode(points[i]));
    em.nodes.push_back(global.back());
  }
  ElementBlock& block = em.block(ElementType::Tet4);
  block.nodes.reserve(block.nodes.size() + tets.size());
  for (std::uint32_t v : tets) block.nodes.push_back(global[v]);
}

// With -Y, TetGen adds no node on the embedded entities; should it still leave one of their
// triangles, segments or points out of the tetrahedra, the mesh is not made.
void requireEmbeddedConformity(const ModelVolume& volume, const Mesh& mesh) {
  if (volume.embeddedSurfaces.empty() && volume.embeddedCurves.empty() &&
      volume.embeddedPoints.empty())
    return;
  const ElementBlock& tets = *mesh.find({3, volume.tag})->findBlock(ElementType::Tet4);
  const std::vector<std::string> defects = embeddedConformityDefects(volume, mesh, tets, 1);
  if (!defects.empty())
    throw MeshError({3, volume.tag},
                    "TetGen could not keep the mesh of an embedded entity without adding nodes "
                    "on it: " +
                        defects.front());
}

// Pyramids on the quadrangles of the shells (see addPyramids), as high as their neighbours
// allow: at a right-angled edge between two recombined faces, two pyramids of the full height
// would meet, so lower ones are tried before the boundary is declared crossing itself. Their
// apexes are nodes of the complex not yet in the mesh (kNoNode). The complex that comes out is
// checked for crossings (rejectIntersections), with or without pyramids.
std::vector<Pyramid> standPyramids(const ModelVolume& volume, VolumePlc& plc,
                                   std::vector<Vec3>& xyz) {
  if (plc.quads.empty()) {
    rejectIntersections(volume, plc, xyz);
    return {};
  }
  const std::vector<Vec3> inward = inwardNormals(plc, xyz, volume.tag);
  constexpr double kHeights[] = {0.4, 0.2, 0.1};
  for (double height : kHeights) {
    VolumePlc trial = plc;
    std::vector<Vec3> places = xyz;
    std::vector<Pyramid> pyramids = addPyramids(trial, places, inward, height);
    try {
      rejectIntersections(volume, trial, places);
    } catch (const MeshError&) {
      if (height == kHeights[std::size(kHeights) - 1]) throw;
      continue;
    }
    plc = std::move(trial);
    xyz = std::move(places);
    return pyramids;
  }
  return {};
}

}  // namespace

VolumeMeshing planVolumeMesh(const Model& model, const MeshOptions& options, int volumeTag,
                             const InteriorSize& interiorSize, const Mesh& mesh,
                             const VolumeProgress& progress) {
  // Shares of the work, as measured on a cube: recovery, refinement, smoothing, optimization.
  constexpr double kRecovered = 0.1, kRefined = 0.7, kSmoothed = 0.8;
  const auto report = [&progress](double fraction) {
    if (progress) progress(fraction);
  };
  const ModelVolume* volume = model.volume(volumeTag);
  if (!volume) throw MeshError({3, volumeTag}, "the volume does not exist");
  VolumeMeshing result;
  result.volume = volumeTag;
  if (isLayeredExtrusion(*volume)) return result;  // structured: meshed by ExtrusionMesher
  VolumePlc& plc = result.plc;
  plc = collectVolumePlc(model, *volume, mesh);
  std::vector<Vec3> xyz;
  for (NodeIndex n : plc.nodes) xyz.push_back(mesh.node(n));
  // Refused before any costly work when it would not fit.
  const double estimate = estimateTetrahedra(plc, xyz, options);
  if (const std::string why = tooManyTetrahedra(estimate); !why.empty())
    throw MeshError({3, volumeTag}, why + " (sizes too small for the volume?)");
  result.pyramids = standPyramids(*volume, plc, xyz);
  rejectEmbeddedOutside(*volume, plc, xyz);
  std::vector<Vec3> holes;
  for (std::size_t s = 1; s < plc.shellStart.size(); ++s) {
    const std::size_t first = plc.shellStart[s], last = plc.shellEndOf(s);
    // An empty shell, or one closed only together with the others (the reference takes a
    // volume's loops as a whole): TetGen carves what no hole point marks from outside in.
    if (last == first || !isClosedShell(plc.triangles, first, last)) continue;
    orientShell(plc.triangles, first, last, xyz);
    holes.push_back(pointInsideShell(plc.triangles, first, last, xyz));
  }
  std::vector<double> plcSizes = plcNodeSizes(plc, xyz, options);
  RefinementSizes sizes;
  DelaunayTets tets = recoverTetrahedra(*volume, plc, xyz, holes, plcSizes, sizes.atVertex);
  report(kRecovered);
  if (progress && estimate > 0)
    sizes.afterRound = [&report, estimate](std::size_t count) {
      const double refined = std::min(1.0, static_cast<double>(count) / estimate);
      report(kRecovered + (kRefined - kRecovered) * refined);
    };
  if (interiorSize) {
    const double factor = options.sizeFactor > 0 ? options.sizeFactor : 1;
    sizes.field = [&interiorSize, factor, &options](Vec3 p) {
      return std::clamp(interiorSize(p) * factor, options.sizeMin, options.sizeMax);
    };
    sizes.extendFromBoundary = options.sizeExtendFromBoundary;
  }
  refineToSizes(tets, sizes);
  report(kRefined);
  const auto firstInterior = static_cast<std::uint32_t>(plc.nodes.size());
  if (options.optimize) smoothVertices(tets, firstInterior, kSmoothingPasses);
  report(kSmoothed);
  result.tets = tets.liveTetrahedra();
  result.points = std::move(tets.points);
  tets = DelaunayTets();  // its links are not needed any more: memory back before optimizing
  optimizeTetrahedra(plc, options, firstInterior, result.points, result.tets);
  report(1);
  return result;
}

void commitVolumeMesh(const Model& model, VolumeMeshing&& planned, Mesh& mesh) {
  if (planned.tets.empty() && planned.plc.nodes.empty()) return;  // layered: nothing planned
  const ModelVolume& volume = *model.volume(planned.volume);
  VolumePlc& plc = planned.plc;
  EntityMesh& em = mesh.entity({3, planned.volume});
  for (std::size_t i = 0; i < plc.nodes.size(); ++i)  // the pyramids' apexes
    if (plc.nodes[i] == kNoNode) {
      plc.nodes[i] = mesh.addNode(planned.points[i]);
      em.nodes.push_back(plc.nodes[i]);
    }
  appendTetrahedra(volume, plc, planned.points, planned.tets, mesh);
  if (!planned.pyramids.empty()) {
    ElementBlock& block = mesh.entity({3, planned.volume}).block(ElementType::Pyramid5);
    for (const Pyramid& p : planned.pyramids)
      for (int k : p) block.nodes.push_back(plc.nodes[k]);
  }
  requireEmbeddedConformity(volume, mesh);
}

void meshVolume(const Model& model, const MeshOptions& options, int volumeTag,
                const InteriorSize& interiorSize, Mesh& mesh) {
  commitVolumeMesh(model, planVolumeMesh(model, options, volumeTag, interiorSize, mesh), mesh);
}

}  // namespace geomesh
