// meshVolume: shells oriented, the complex checked for intersections exactly, then TetGen.
#include "mesh/volumes/volume_mesher.h"

#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mesh/structured/extrusion_mesher.h"
#include "mesh/core/mesh_error.h"
#include "mesh/volumes/abort_trap.h"
#include "mesh/volumes/embedded_conformity.h"
#include "mesh/volumes/plc_containment.h"
#include "mesh/volumes/plc_intersections.h"
#include "mesh/volumes/pyramid_bases.h"
#include "mesh/volumes/tet_optimizer.h"
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
  TetgenInput(const VolumePlc& plc, const std::vector<Vec3>& xyz, std::vector<double> sizes,
              const std::vector<Vec3>& holes);
  ~TetgenInput() { release(); }
  TetgenInput(const TetgenInput&) = delete;
  TetgenInput& operator=(const TetgenInput&) = delete;
  tetgenio& io() { return io_; }

 private:
  void release();

  std::vector<double> points_, sizes_, holes_;
  std::vector<int> corners_, edges_;
  std::vector<tetgenio::polygon> polygons_;
  std::vector<tetgenio::facet> facets_;
  tetgenio io_;
};

TetgenInput::TetgenInput(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                         std::vector<double> sizes, const std::vector<Vec3>& holes)
    : sizes_(std::move(sizes)) {
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
  io_.numberofpointmtrs = 1;
  io_.pointmtrlist = sizes_.data();
  io_.numberoffacets = static_cast<int>(facets_.size());
  io_.facetlist = facets_.data();
  io_.numberofholes = static_cast<int>(holes.size());
  io_.holelist = holes_.empty() ? nullptr : holes_.data();
  io_.numberofedges = static_cast<int>(plc.segments.size());
  io_.edgelist = edges_.empty() ? nullptr : edges_.data();
}

void TetgenInput::release() {
  io_.pointlist = nullptr;
  io_.pointmtrlist = nullptr;
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
bool tetrahedralizeBoundary(const ModelVolume& volume, TetgenInput& input, tetgenio& output,
                            tetgenio* background) {
  // p: boundary given as facets; Y: no node added on it; q2.0: radius-edge ratio bound (a
  // tighter one or a dihedral angle bound adds 5-20% tetrahedra, and the slivers left near the
  // boundary are the optimizer's work either way); m: sizes at the points; z: zero-based
  // numbering; Q: quiet.
  char switches[] = "pYq2.0mzQ";
  try {
    return runTrappingAbort(
        [&] { tetrahedralize(switches, &input.io(), &output, nullptr, background); });
  } catch (int code) {
    throw MeshError({3, volume.tag}, tetgenFailure(code));
  }
}

// A background mesh for TetGen: the nodes and tetrahedra of a mesh it made, borrowed, with a
// size at each node.
class TetgenBackground {
 public:
  TetgenBackground(tetgenio& mesh, std::vector<double> sizes) : sizes_(std::move(sizes)) {
    io_.firstnumber = 0;
    io_.numberofpoints = mesh.numberofpoints;
    io_.pointlist = mesh.pointlist;
    io_.numberoftetrahedra = mesh.numberoftetrahedra;
    io_.numberofcorners = mesh.numberofcorners;
    io_.tetrahedronlist = mesh.tetrahedronlist;
    io_.numberofpointmtrs = 1;
    io_.pointmtrlist = sizes_.data();
  }
  ~TetgenBackground() {
    io_.pointlist = nullptr;
    io_.tetrahedronlist = nullptr;
    io_.pointmtrlist = nullptr;
  }
  TetgenBackground(const TetgenBackground&) = delete;
  TetgenBackground& operator=(const TetgenBackground&) = delete;
  tetgenio& io() { return io_; }

 private:
  std::vector<double> sizes_;
  tetgenio io_;
};

// Remakes the mesh sized by the interior size at the nodes of the previous one (each node's
// boundary size, or the size TetGen interpolated there, bounding it when sizes extend from the
// boundary), until the node count settles (at most a few times).
std::unique_ptr<tetgenio> followInteriorSize(const ModelVolume& volume, TetgenInput& input,
                                             const std::vector<double>& plcSizes,
                                             const InteriorSize& interiorSize,
                                             const MeshOptions& options,
                                             std::unique_ptr<tetgenio> mesh) {
  constexpr int kPasses = 4;
  constexpr double kSettled = 0.03;  // relative change of the node count
  const double factor = options.sizeFactor > 0 ? options.sizeFactor : 1;
  for (int pass = 0; pass < kPasses; ++pass) {
    const int before = mesh->numberofpoints;
    std::vector<double> sizes(static_cast<std::size_t>(before));
    // All sizes as TetGen reads them (see kTetgenSizeScale), as plcSizes are.
    for (int i = 0; i < before; ++i) {
      const double* p = mesh->pointlist + 3 * i;
      sizes[i] = kTetgenSizeScale * std::clamp(interiorSize({p[0], p[1], p[2]}) * factor,
                                               options.sizeMin, options.sizeMax);
      if (i < static_cast<int>(plcSizes.size()))
        sizes[i] = std::min(sizes[i], plcSizes[i]);
      else if (options.sizeExtendFromBoundary && mesh->pointmtrlist)
        sizes[i] = std::min(sizes[i], mesh->pointmtrlist[i]);
    }
    TetgenBackground background(*mesh, std::move(sizes));
    auto next = std::make_unique<tetgenio>();
    // A pass that aborts (see tetrahedralizeBoundary) leaves the previous mesh.
    if (!tetrahedralizeBoundary(volume, input, *next, &background.io())) break;
    const int after = next->numberofpoints;
    mesh = std::move(next);
    if (std::abs(after - before) <= kSettled * before) break;
  }
  return mesh;
}

// Adds TetGen's new points to the volume and its tetrahedra, positively oriented.
void appendTetrahedra(const ModelVolume& volume, const VolumePlc& plc, const tetgenio& out,
                      Mesh& mesh) {
  const EntityId id{3, volume.tag};
  if (out.numberofpoints < static_cast<int>(plc.nodes.size()) || out.numberofcorners != 4 ||
      out.numberoftetrahedra <= 0)
    throw MeshError(id, "TetGen returned no tetrahedra");
  for (std::size_t i = 0; i < plc.nodes.size(); ++i) {
    const double* p = out.pointlist + 3 * i;
    if (!(Vec3{p[0], p[1], p[2]} == mesh.node(plc.nodes[i])))
      throw MeshError(id, "TetGen moved a boundary node");
  }
  EntityMesh& em = mesh.entity(id);
  std::vector<NodeIndex> global(plc.nodes);
  for (int i = static_cast<int>(plc.nodes.size()); i < out.numberofpoints; ++i) {
    const double* p = out.pointlist + 3 * i;
    global.push_back(mesh.addNode({p[0], p[1], p[2]}));
    em.nodes.push_back(global.back());
  }
  ElementBlock& tets = em.block(ElementType::Tet4);
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    const int* c = out.tetrahedronlist + 4 * t;
    std::array<NodeIndex, 4> n{global[c[0]], global[c[1]], global[c[2]], global[c[3]]};
    if (signedTetVolume(mesh.node(n[0]), mesh.node(n[1]), mesh.node(n[2]), mesh.node(n[3])) < 0)
      std::swap(n[0], n[1]);
    tets.nodes.insert(tets.nodes.end(), n.begin(), n.end());
  }
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
// apexes become nodes of the volume. The complex that comes out is checked for crossings
// (rejectIntersections), with or without pyramids.
std::vector<Pyramid> standPyramids(const ModelVolume& volume, VolumePlc& plc,
                                   std::vector<Vec3>& xyz, Mesh& mesh) {
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
    EntityMesh& em = mesh.entity({3, volume.tag});
    for (std::size_t i = 0; i < trial.nodes.size(); ++i)
      if (trial.nodes[i] == kNoNode) {
        trial.nodes[i] = mesh.addNode(places[i]);
        em.nodes.push_back(trial.nodes[i]);
      }
    plc = std::move(trial);
    xyz = std::move(places);
    return pyramids;
  }
  return {};
}

// The embedded surfaces' triangles and curves' segments, in mesh nodes.
KeptInside keptInside(const VolumePlc& plc) {
  KeptInside kept;
  for (std::size_t t = plc.shellEnd; t < plc.triangles.size(); ++t) {
    const PlcTriangle& c = plc.triangles[t];
    kept.triangles.push_back({plc.nodes[c[0]], plc.nodes[c[1]], plc.nodes[c[2]]});
  }
  for (const PlcSegment& s : plc.segments)
    kept.segments.push_back({plc.nodes[s[0]], plc.nodes[s[1]]});
  return kept;
}

}  // namespace

void meshVolume(const Model& model, const MeshOptions& options, int volumeTag,
                const InteriorSize& interiorSize, Mesh& mesh) {
  const ModelVolume* volume = model.volume(volumeTag);
  if (!volume) throw MeshError({3, volumeTag}, "the volume does not exist");
  if (isLayeredExtrusion(*volume)) return;  // structured: meshed by ExtrusionMesher
  VolumePlc plc = collectVolumePlc(model, *volume, mesh);
  std::vector<Vec3> xyz;
  for (NodeIndex n : plc.nodes) xyz.push_back(mesh.node(n));
  const std::vector<Pyramid> pyramids = standPyramids(*volume, plc, xyz, mesh);
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
  constexpr int kOrders = 3;
  for (int attempt = 0;; ++attempt) {
    if (attempt > 0) renumberPlc(plc, xyz, plcSizes, plc.nodes.size() / (attempt + 1) + 1);
    TetgenInput input(plc, xyz, plcSizes, holes);
    auto output = std::make_unique<tetgenio>();
    if (tetrahedralizeBoundary(*volume, input, *output, nullptr)) {
      if (interiorSize)
        output =
            followInteriorSize(*volume, input, plcSizes, interiorSize, options, std::move(output));
      appendTetrahedra(*volume, plc, *output, mesh);
      if (!pyramids.empty()) {
        ElementBlock& block = mesh.entity({3, volumeTag}).block(ElementType::Pyramid5);
        for (const Pyramid& p : pyramids)
          for (int k : p) block.nodes.push_back(plc.nodes[k]);
      }
      break;
    }
    if (attempt + 1 == kOrders)
      throw MeshError({3, volumeTag}, "TetGen failed an internal check on its boundary mesh in " +
                                          std::to_string(kOrders) +
                                          " orders of its nodes (a degenerate configuration)");
  }
  requireEmbeddedConformity(*volume, mesh);
  if (options.optimize) {
    KeptInside kept = keptInside(plc);
    for (const Pyramid& p : pyramids) kept.fixedNodes.push_back(plc.nodes[p[4]]);  // apexes
    optimizeTetrahedra(mesh, {3, volumeTag}, options.optimizeThreshold, kept);
  }
}

}  // namespace geomesh
