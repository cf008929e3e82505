#include "mesh/volume_mesher.h"

#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/generate.h"

namespace geomesh {

namespace {

using Triangle = std::array<int, 3>;  // local indices into BoundaryMesh::nodes

// The closed triangulated boundary of a volume, with its own compact node numbering.
struct BoundaryMesh {
  std::vector<NodeIndex> nodes;       // local -> mesh node
  std::vector<Triangle> triangles;
  std::vector<std::size_t> shellStart;  // first triangle of each shell; outer shell first
};

int localIndex(BoundaryMesh& b, std::unordered_map<NodeIndex, int>& local, NodeIndex n) {
  auto [it, inserted] = local.try_emplace(n, static_cast<int>(b.nodes.size()));
  if (inserted) b.nodes.push_back(n);
  return it->second;
}

BoundaryMesh collectBoundary(const ModelVolume& volume, const Mesh& mesh) {
  const EntityId id{3, volume.tag};
  BoundaryMesh b;
  std::unordered_map<NodeIndex, int> local;
  for (const std::vector<int>& shell : volume.shells) {
    b.shellStart.push_back(b.triangles.size());
    for (int signedSurface : shell) {
      const int s = std::abs(signedSurface);
      const EntityMesh* em = mesh.find({2, s});
      const ElementBlock* tris = em ? em->findBlock(ElementType::Triangle3) : nullptr;
      if (!tris || tris->size() == 0)
        throw MeshError(id, "surface " + std::to_string(s) + " has no triangle mesh");
      if (em->elementCount() != tris->size())
        throw MeshError(id, "surface " + std::to_string(s) +
                                " has elements other than 3-node triangles");
      for (std::size_t i = 0; i < tris->size(); ++i) {
        const auto t = tris->element(i);
        b.triangles.push_back(
            {localIndex(b, local, t[0]), localIndex(b, local, t[1]), localIndex(b, local, t[2])});
      }
    }
  }
  if (b.triangles.size() < 4) throw MeshError(id, "its boundary has fewer than 4 triangles");
  return b;
}

double signedTetVolume(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return dot(cross(b - a, c - a), d - a) / 6;
}

// Orients the triangles [first, last) consistently (each edge traversed once each way), by a
// walk across shared edges, then outward (positive enclosed volume).
void orientShell(std::vector<Triangle>& tris, std::size_t first, std::size_t last,
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

// A point inside an inner shell (a hole of the volume), just behind its largest triangle: the
// shell must be oriented outward.
Vec3 pointInsideShell(const std::vector<Triangle>& tris, std::size_t first, std::size_t last,
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

// Target size at each boundary node: the mean length of its boundary edges, within the
// allowed range.
std::vector<double> boundaryNodeSizes(const BoundaryMesh& b, const std::vector<Vec3>& xyz,
                                      const MeshOptions& options) {
  std::vector<double> sum(b.nodes.size(), 0);
  std::vector<int> count(b.nodes.size(), 0);
  for (const Triangle& t : b.triangles)
    for (int k = 0; k < 3; ++k) {
      const int p = t[k], q = t[(k + 1) % 3];
      const double length = distance(xyz[p], xyz[q]);
      sum[p] += length;
      sum[q] += length;
      ++count[p];
      ++count[q];
    }
  std::vector<double> size(b.nodes.size());
  for (std::size_t i = 0; i < size.size(); ++i)
    size[i] = std::clamp(sum[i] / std::max(count[i], 1), options.sizeMin, options.sizeMax);
  return size;
}

// TetGen's input, pointing into arrays owned here. tetgenio frees its arrays with delete[] on
// destruction, so the borrowed pointers are cleared first.
class TetgenInput {
 public:
  TetgenInput(const BoundaryMesh& b, const std::vector<Vec3>& xyz, std::vector<double> sizes,
              const std::vector<Vec3>& holes);
  ~TetgenInput() { release(); }
  TetgenInput(const TetgenInput&) = delete;
  TetgenInput& operator=(const TetgenInput&) = delete;
  tetgenio& io() { return io_; }

 private:
  void release();

  std::vector<double> points_, sizes_, holes_;
  std::vector<int> corners_;
  std::vector<tetgenio::polygon> polygons_;
  std::vector<tetgenio::facet> facets_;
  tetgenio io_;
};

TetgenInput::TetgenInput(const BoundaryMesh& b, const std::vector<Vec3>& xyz,
                         std::vector<double> sizes, const std::vector<Vec3>& holes)
    : sizes_(std::move(sizes)) {
  for (Vec3 p : xyz) points_.insert(points_.end(), {p.x, p.y, p.z});
  for (Vec3 h : holes) holes_.insert(holes_.end(), {h.x, h.y, h.z});
  for (const Triangle& t : b.triangles) corners_.insert(corners_.end(), t.begin(), t.end());
  polygons_.resize(b.triangles.size());
  facets_.resize(b.triangles.size());
  for (std::size_t i = 0; i < b.triangles.size(); ++i) {
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
}

void TetgenInput::release() {
  io_.pointlist = nullptr;
  io_.pointmtrlist = nullptr;
  io_.facetlist = nullptr;
  io_.numberoffacets = 0;
  io_.holelist = nullptr;
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

// TetGen 1.5 releases its memory twice when it gives up on an input (a crash instead of the
// error it throws), so intersecting boundaries, the usual cause, are detected first: in its
// diagnosis mode TetGen returns the intersecting facets instead of failing.
void rejectSelfIntersections(const ModelVolume& volume, TetgenInput& input) {
  char switches[] = "pdzQ";
  tetgenio intersecting;
  try {
    tetrahedralize(switches, &input.io(), &intersecting);
  } catch (int code) {
    throw MeshError({3, volume.tag}, tetgenFailure(code));
  }
  if (intersecting.numberoftrifaces > 0)
    throw MeshError({3, volume.tag},
                    "its boundary surfaces intersect each other (" +
                        std::to_string(intersecting.numberoftrifaces) + " triangles involved)");
}

void tetrahedralizeBoundary(const ModelVolume& volume, TetgenInput& input, tetgenio& output) {
  // p: boundary given as facets; Y: no node added on it; q: radius-edge ratio bound; m: sizes
  // at the points; z: zero-based numbering; Q: quiet.
  char switches[] = "pYq1.5mzQ";
  try {
    tetrahedralize(switches, &input.io(), &output);
  } catch (int code) {
    throw MeshError({3, volume.tag}, tetgenFailure(code));
  }
}

// Adds TetGen's new points to the volume and its tetrahedra, positively oriented.
void appendTetrahedra(const ModelVolume& volume, const BoundaryMesh& b, const tetgenio& out,
                      Mesh& mesh) {
  const EntityId id{3, volume.tag};
  if (out.numberofpoints < static_cast<int>(b.nodes.size()) || out.numberofcorners != 4 ||
      out.numberoftetrahedra <= 0)
    throw MeshError(id, "TetGen returned no tetrahedra");
  for (std::size_t i = 0; i < b.nodes.size(); ++i) {
    const double* p = out.pointlist + 3 * i;
    if (!(Vec3{p[0], p[1], p[2]} == mesh.node(b.nodes[i])))
      throw MeshError(id, "TetGen moved a boundary node");
  }
  EntityMesh& em = mesh.entity(id);
  std::vector<NodeIndex> global(b.nodes);
  for (int i = static_cast<int>(b.nodes.size()); i < out.numberofpoints; ++i) {
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

}  // namespace

void meshVolume(const Model& model, const MeshOptions& options, int volumeTag, Mesh& mesh) {
  const ModelVolume* volume = model.volume(volumeTag);
  if (!volume) throw MeshError({3, volumeTag}, "the volume does not exist");
  BoundaryMesh boundary = collectBoundary(*volume, mesh);
  std::vector<Vec3> xyz;
  for (NodeIndex n : boundary.nodes) xyz.push_back(mesh.node(n));
  std::vector<Vec3> holes;
  for (std::size_t s = 1; s < boundary.shellStart.size(); ++s) {
    const std::size_t last =
        s + 1 < boundary.shellStart.size() ? boundary.shellStart[s + 1] : boundary.triangles.size();
    if (last == boundary.shellStart[s]) continue;  // an empty shell
    orientShell(boundary.triangles, boundary.shellStart[s], last, xyz);
    holes.push_back(pointInsideShell(boundary.triangles, boundary.shellStart[s], last, xyz));
  }
  TetgenInput input(boundary, xyz, boundaryNodeSizes(boundary, xyz, options), holes);
  rejectSelfIntersections(*volume, input);
  tetgenio output;
  tetrahedralizeBoundary(*volume, input, output);
  appendTetrahedra(*volume, boundary, output, mesh);
}

}  // namespace geomesh
