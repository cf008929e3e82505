// meshVolume: boundary shells oriented, self-intersections rejected exactly, then TetGen.
#include "mesh/volumes/volume_mesher.h"

#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/structured/extrusion_mesher.h"
#include "mesh/core/mesh_error.h"
#include "mesh/core/predicates.h"
#include "mesh/volumes/abort_trap.h"
#include "mesh/volumes/tet_optimizer.h"

namespace geomesh {

namespace {

using Triangle = std::array<int, 3>;  // local indices into BoundaryMesh::nodes

// The closed triangulated boundary of a volume, with its own compact node numbering.
struct BoundaryMesh {
  std::vector<NodeIndex> nodes;       // local -> mesh node
  std::vector<Triangle> triangles;
  std::vector<std::size_t> shellStart;  // first triangle of each shell; outer shell first
  std::vector<int> surfaceOf;           // per triangle
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
        b.surfaceOf.push_back(s);
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

// TetGen adds nodes until no edge is much longer than the size asked for; a Delaunay mesh
// whose nodes lie a size apart, as the reference makes, has longer edges on average. The
// sizes given to TetGen are scaled by this factor, which brings the node counts to the
// reference's (within 10% on boxes, spheres, lofts, CAD parts and size fields).
constexpr double kTetgenSizeScale = 1.15;

// Target size at each boundary node (as TetGen reads it: see kTetgenSizeScale): the mean
// length of its boundary edges, within the allowed range.
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
    size[i] = kTetgenSizeScale *
              std::clamp(sum[i] / std::max(count[i], 1), options.sizeMin, options.sizeMax);
  return size;
}

// --- Boundary self-intersections -------------------------------------------------------------
// TetGen 1.5 crashes (it releases its memory twice) when it gives up on an input, typically a
// boundary whose triangles cross each other, so such boundaries are detected first, exactly:
// two triangles may only share the vertices or the edge they have in common.

// Orientations within one plane: drops the coordinate along which the plane's normal is
// largest; for points of that plane the 2D signs are exact (up to one common sign).
struct PlaneProjection {
  int axis;
  explicit PlaneProjection(const Vec3 t[3]) {
    const Vec3 n = cross(t[1] - t[0], t[2] - t[0]);
    const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
    axis = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
  }
  Vec2 operator()(Vec3 p) const {
    return axis == 0 ? Vec2{p.y, p.z} : (axis == 1 ? Vec2{p.z, p.x} : Vec2{p.x, p.y});
  }
};

bool onSegment2d(Vec2 p, Vec2 a, Vec2 b) {  // p collinear with a, b
  return std::min(a.u, b.u) <= p.u && p.u <= std::max(a.u, b.u) && std::min(a.v, b.v) <= p.v &&
         p.v <= std::max(a.v, b.v);
}

bool segmentsMeet2d(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const int o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && onSegment2d(c, a, b)) || (o2 == 0 && onSegment2d(d, a, b)) ||
         (o3 == 0 && onSegment2d(a, c, d)) || (o4 == 0 && onSegment2d(b, c, d));
}

bool insideTriangle2d(Vec2 p, const Vec2 t[3]) {
  const int o = orient2d(t[0], t[1], t[2]);
  for (int k = 0; k < 3; ++k)
    if (orient2d(t[k], t[(k + 1) % 3], p) * o < 0) return false;
  return true;
}

// Whether the closed segment [a, b] meets the closed triangle t.
bool segmentMeetsTriangle(Vec3 a, Vec3 b, const Vec3 t[3]) {
  const int sa = orient3d(t[0], t[1], t[2], a), sb = orient3d(t[0], t[1], t[2], b);
  if (sa == sb && sa != 0) return false;
  if (sa == 0 && sb == 0) {
    const PlaneProjection flat(t);
    const Vec2 t2[3] = {flat(t[0]), flat(t[1]), flat(t[2])};
    const Vec2 a2 = flat(a), b2 = flat(b);
    if (insideTriangle2d(a2, t2) || insideTriangle2d(b2, t2)) return true;
    for (int k = 0; k < 3; ++k)
      if (segmentsMeet2d(a2, b2, t2[k], t2[(k + 1) % 3])) return true;
    return false;
  }
  const int o0 = orient3d(a, b, t[0], t[1]), o1 = orient3d(a, b, t[1], t[2]);
  const int o2 = orient3d(a, b, t[2], t[0]);
  return (o0 >= 0 && o1 >= 0 && o2 >= 0) || (o0 <= 0 && o1 <= 0 && o2 <= 0);
}

// Whether the segment from t[0] towards x runs inside the closed corner of triangle t at t[0].
bool insideCorner(Vec3 x, const Vec3 t[3]) {
  if (orient3d(t[0], t[1], t[2], x) != 0) return false;
  const PlaneProjection flat(t);
  const Vec2 v = flat(t[0]), c = flat(t[1]), d = flat(t[2]), p = flat(x);
  const int o = orient2d(v, c, d);
  return orient2d(v, c, p) * o >= 0 && orient2d(v, p, d) * o >= 0;
}

// Rotates triangle t so that its corners shared with u come first; returns how many there are.
int shareCorners(Triangle& t, const Triangle& u) {
  auto shared = [&](int i) { return std::find(u.begin(), u.end(), i) != u.end(); };
  std::stable_partition(t.begin(), t.end(), shared);
  return static_cast<int>(std::count_if(t.begin(), t.end(), shared));
}

bool trianglesCross(Triangle i, Triangle j, const std::vector<Vec3>& xyz) {
  const int shared = shareCorners(i, j);
  shareCorners(j, i);
  const Vec3 p[3] = {xyz[i[0]], xyz[i[1]], xyz[i[2]]};
  const Vec3 q[3] = {xyz[j[0]], xyz[j[1]], xyz[j[2]]};
  switch (shared) {
    case 0:
      for (int k = 0; k < 3; ++k)
        if (segmentMeetsTriangle(p[k], p[(k + 1) % 3], q) ||
            segmentMeetsTriangle(q[k], q[(k + 1) % 3], p))
          return true;
      return false;
    case 1:  // p[0] == q[0]
      return segmentMeetsTriangle(p[1], p[2], q) || segmentMeetsTriangle(q[1], q[2], p) ||
             insideCorner(p[1], q) || insideCorner(p[2], q) || insideCorner(q[1], p) ||
             insideCorner(q[2], p);
    case 2: {  // a fold: both on the same side of their common edge, in one plane
      if (orient3d(p[0], p[1], p[2], q[2]) != 0) return false;
      const PlaneProjection flat(p);
      return orient2d(flat(p[0]), flat(p[1]), flat(p[2])) *
                 orient2d(flat(p[0]), flat(p[1]), flat(q[2])) >
             0;
    }
    default: return true;  // the same triangle twice
  }
}

// Candidate pairs come from a uniform grid of cells about the size of the triangles.
class TriangleGrid {
 public:
  TriangleGrid(const std::vector<Triangle>& tris, const std::vector<Vec3>& xyz);
  template <class Visit>
  void forCells(const BoundingBox& box, Visit visit) const;
  const std::vector<std::uint32_t>* cell(std::size_t key) const;  // null when empty
  BoundingBox boxOf(const Triangle& t) const;

 private:
  std::array<std::size_t, 3> cellOf(Vec3 p) const;
  const std::vector<Vec3>& xyz_;
  BoundingBox all_;
  double cellSize_ = 1;
  std::array<std::size_t, 3> dims_{1, 1, 1};
  std::unordered_map<std::size_t, std::vector<std::uint32_t>> cells_;
};

BoundingBox TriangleGrid::boxOf(const Triangle& t) const {
  BoundingBox box;
  for (int k : t) box.include(xyz_[k]);
  return box;
}

TriangleGrid::TriangleGrid(const std::vector<Triangle>& tris, const std::vector<Vec3>& xyz)
    : xyz_(xyz) {
  double sum = 0;
  for (const Triangle& t : tris) {
    const BoundingBox box = boxOf(t);
    all_.include(box);
    sum += distance(box.min, box.max);
  }
  const Vec3 extent = all_.max - all_.min;
  // About one triangle per cell, and no more cells than a few per triangle.
  cellSize_ = std::max({sum / static_cast<double>(tris.size()), 1e-300,
                        std::cbrt(extent.x * extent.y * extent.z / (4.0 * tris.size()))});
  dims_ = {static_cast<std::size_t>(extent.x / cellSize_) + 1,
           static_cast<std::size_t>(extent.y / cellSize_) + 1,
           static_cast<std::size_t>(extent.z / cellSize_) + 1};
  for (std::size_t i = 0; i < tris.size(); ++i)
    forCells(boxOf(tris[i]), [&](std::size_t key) {
      cells_[key].push_back(static_cast<std::uint32_t>(i));
    });
}

std::array<std::size_t, 3> TriangleGrid::cellOf(Vec3 p) const {
  auto index = [&](double x, double lo, std::size_t n) {
    return std::min(static_cast<std::size_t>(std::max(0.0, (x - lo) / cellSize_)), n - 1);
  };
  return {index(p.x, all_.min.x, dims_[0]), index(p.y, all_.min.y, dims_[1]),
          index(p.z, all_.min.z, dims_[2])};
}

template <class Visit>
void TriangleGrid::forCells(const BoundingBox& box, Visit visit) const {
  const auto lo = cellOf(box.min), hi = cellOf(box.max);
  for (std::size_t i = lo[0]; i <= hi[0]; ++i)
    for (std::size_t j = lo[1]; j <= hi[1]; ++j)
      for (std::size_t k = lo[2]; k <= hi[2]; ++k) visit((i * dims_[1] + j) * dims_[2] + k);
}

const std::vector<std::uint32_t>* TriangleGrid::cell(std::size_t key) const {
  auto it = cells_.find(key);
  return it == cells_.end() ? nullptr : &it->second;
}

bool boxesOverlap(const BoundingBox& a, const BoundingBox& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
         b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

void rejectSelfIntersections(const ModelVolume& volume, const BoundaryMesh& b,
                             const std::vector<Vec3>& xyz) {
  const TriangleGrid grid(b.triangles, xyz);
  std::vector<std::size_t> lastVisit(b.triangles.size(), SIZE_MAX);
  for (std::size_t i = 0; i < b.triangles.size(); ++i) {
    const BoundingBox box = grid.boxOf(b.triangles[i]);
    grid.forCells(box, [&](std::size_t key) {
      const std::vector<std::uint32_t>* cell = grid.cell(key);
      for (std::uint32_t j : cell ? *cell : std::vector<std::uint32_t>{}) {
        if (j >= i || lastVisit[j] == i) continue;
        lastVisit[j] = i;
        if (!boxesOverlap(box, grid.boxOf(b.triangles[j])) ||
            !trianglesCross(b.triangles[i], b.triangles[j], xyz))
          continue;
        const Vec3 at = xyz[b.triangles[i][0]];
        throw MeshError({3, volume.tag},
                        "its boundary intersects itself: a triangle of surface " +
                            std::to_string(b.surfaceOf[i]) + " crosses one of surface " +
                            std::to_string(b.surfaceOf[j]) + " near (" + std::to_string(at.x) +
                            ", " + std::to_string(at.y) + ", " + std::to_string(at.z) + ")");
      }
    });
  }
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

// Renumbers the boundary's nodes by i -> i * stride mod n, with the stride the first integer
// from `start` coprime with n, so that TetGen meets the points in another order.
void renumber(BoundaryMesh& b, std::vector<Vec3>& xyz, std::vector<double>& sizes,
              std::size_t start) {
  const std::size_t n = b.nodes.size();
  std::size_t stride = std::max<std::size_t>(start, 1);
  while (std::gcd(stride, n) != 1) ++stride;
  std::vector<int> to(n);
  for (std::size_t i = 0; i < n; ++i) to[i] = static_cast<int>(i * stride % n);
  std::vector<NodeIndex> nodes(n);
  std::vector<Vec3> places(n);
  std::vector<double> targets(n);
  for (std::size_t i = 0; i < n; ++i) {
    nodes[to[i]] = b.nodes[i];
    places[to[i]] = xyz[i];
    targets[to[i]] = sizes[i];
  }
  b.nodes = std::move(nodes);
  xyz = std::move(places);
  sizes = std::move(targets);
  for (Triangle& t : b.triangles)
    for (int& k : t) k = to[k];
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
                                             const std::vector<double>& boundarySizes,
                                             const InteriorSize& interiorSize,
                                             const MeshOptions& options,
                                             std::unique_ptr<tetgenio> mesh) {
  constexpr int kPasses = 4;
  constexpr double kSettled = 0.03;  // relative change of the node count
  const double factor = options.sizeFactor > 0 ? options.sizeFactor : 1;
  for (int pass = 0; pass < kPasses; ++pass) {
    const int before = mesh->numberofpoints;
    std::vector<double> sizes(static_cast<std::size_t>(before));
    // All sizes as TetGen reads them (see kTetgenSizeScale), as boundarySizes are.
    for (int i = 0; i < before; ++i) {
      const double* p = mesh->pointlist + 3 * i;
      sizes[i] = kTetgenSizeScale * std::clamp(interiorSize({p[0], p[1], p[2]}) * factor,
                                               options.sizeMin, options.sizeMax);
      if (i < static_cast<int>(boundarySizes.size()))
        sizes[i] = std::min(sizes[i], boundarySizes[i]);
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

void meshVolume(const Model& model, const MeshOptions& options, int volumeTag,
                const InteriorSize& interiorSize, Mesh& mesh) {
  const ModelVolume* volume = model.volume(volumeTag);
  if (!volume) throw MeshError({3, volumeTag}, "the volume does not exist");
  if (isLayeredExtrusion(*volume)) return;  // structured: meshed by ExtrusionMesher
  BoundaryMesh boundary = collectBoundary(*volume, mesh);
  std::vector<Vec3> xyz;
  for (NodeIndex n : boundary.nodes) xyz.push_back(mesh.node(n));
  rejectSelfIntersections(*volume, boundary, xyz);
  std::vector<Vec3> holes;
  for (std::size_t s = 1; s < boundary.shellStart.size(); ++s) {
    const std::size_t last =
        s + 1 < boundary.shellStart.size() ? boundary.shellStart[s + 1] : boundary.triangles.size();
    if (last == boundary.shellStart[s]) continue;  // an empty shell
    orientShell(boundary.triangles, boundary.shellStart[s], last, xyz);
    holes.push_back(pointInsideShell(boundary.triangles, boundary.shellStart[s], last, xyz));
  }
  std::vector<double> boundarySizes = boundaryNodeSizes(boundary, xyz, options);
  constexpr int kOrders = 3;
  for (int attempt = 0;; ++attempt) {
    if (attempt > 0)
      renumber(boundary, xyz, boundarySizes, boundary.nodes.size() / (attempt + 1) + 1);
    TetgenInput input(boundary, xyz, boundarySizes, holes);
    auto output = std::make_unique<tetgenio>();
    if (tetrahedralizeBoundary(*volume, input, *output, nullptr)) {
      if (interiorSize)
        output = followInteriorSize(*volume, input, boundarySizes, interiorSize, options,
                                    std::move(output));
      appendTetrahedra(*volume, boundary, *output, mesh);
      break;
    }
    if (attempt + 1 == kOrders)
      throw MeshError({3, volumeTag}, "TetGen failed an internal check on its boundary mesh in " +
                                          std::to_string(kOrders) +
                                          " orders of its nodes (a degenerate configuration)");
  }
  if (options.optimize) optimizeTetrahedra(mesh, {3, volumeTag}, options.optimizeThreshold);
}

}  // namespace geomesh
