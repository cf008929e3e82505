// rejectIntersections: exact tests between triangles, segments and points, over a uniform grid.
#include "mesh/volumes/plc_intersections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "mesh/core/mesh_error.h"
#include "mesh/core/predicates.h"

namespace geomesh {

namespace {

// A piece of the complex: a triangle, a segment or a point, by its first `size` corners.
struct Piece {
  std::array<int, 3> corners;
  int size;
};

// Orientations within one plane: drops the coordinate along which the plane's normal is
// largest; for points of that plane the 2D signs are exact (up to one common sign), provided
// the plane is not parallel to the dropped axis.
struct PlaneProjection {
  int axis;
  explicit PlaneProjection(Vec3 normal) {
    const double ax = std::abs(normal.x), ay = std::abs(normal.y), az = std::abs(normal.z);
    axis = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
  }
  explicit PlaneProjection(const Vec3 t[3]) : PlaneProjection(cross(t[1] - t[0], t[2] - t[0])) {}
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

// Exact: three points are collinear when their projections on the three axis planes are.
bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == 0 &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == 0 &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == 0;
}

bool insideBox(Vec3 p, Vec3 a, Vec3 b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y) && std::min(a.z, b.z) <= p.z && p.z <= std::max(a.z, b.z);
}

// Whether the closed segment [a, b] holds p.
bool onSegment(Vec3 p, Vec3 a, Vec3 b) {
  return collinear(a, b, p) && insideBox(p, a, b);
}

// Whether the closed triangle t holds p.
bool onTriangle(Vec3 p, const Vec3 t[3]) {
  if (orient3d(t[0], t[1], t[2], p) != 0) return false;
  const PlaneProjection flat(t);
  const Vec2 t2[3] = {flat(t[0]), flat(t[1]), flat(t[2])};
  return insideTriangle2d(flat(p), t2);
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

// Whether the closed segments [a, b] and [c, d] meet.
bool segmentsMeet(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  if (orient3d(a, b, c, d) != 0) return false;
  // Any normal of their common plane will do; for collinear segments, a plane along them.
  Vec3 normal = cross(b - a, c - a);
  for (Vec3 other : {cross(b - a, d - a), cross(d - c, a - c)})
    if (norm(other) > norm(normal)) normal = other;
  if (!(norm(normal) > 0)) {
    const Vec3 along = b - a;
    const double ax = std::abs(along.x), ay = std::abs(along.y), az = std::abs(along.z);
    normal = ax <= ay && ax <= az ? Vec3{1, 0, 0} : (ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  }
  const PlaneProjection flat(normal);
  return segmentsMeet2d(flat(a), flat(b), flat(c), flat(d));
}

// For b and d collinear with a: whether they lie on the same side of it.
bool sameSide(Vec3 a, Vec3 b, Vec3 d) {
  auto same = [](double o, double p, double q) { return (p > o && q > o) || (p < o && q < o); };
  return same(a.x, b.x, d.x) || same(a.y, b.y, d.y) || same(a.z, b.z, d.z);
}

// Whether the segment from t[0] towards x runs inside the closed corner of triangle t at t[0].
bool insideCorner(Vec3 x, const Vec3 t[3]) {
  if (orient3d(t[0], t[1], t[2], x) != 0) return false;
  const PlaneProjection flat(t);
  const Vec2 v = flat(t[0]), c = flat(t[1]), d = flat(t[2]), p = flat(x);
  const int o = orient2d(v, c, d);
  return orient2d(v, c, p) * o >= 0 && orient2d(v, p, d) * o >= 0;
}

// Rotates the corners of p shared with q to the front; returns how many there are.
int shareCorners(Piece& p, const Piece& q) {
  auto shared = [&](int i) {
    return std::find(q.corners.begin(), q.corners.begin() + q.size, i) !=
           q.corners.begin() + q.size;
  };
  const auto end = p.corners.begin() + p.size;
  std::stable_partition(p.corners.begin(), end, shared);
  return static_cast<int>(std::count_if(p.corners.begin(), end, shared));
}

bool trianglesCross(int shared, const Vec3 p[3], const Vec3 q[3]) {
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
    default:
      return true;  // the same triangle twice
  }
}

// Whether two pieces meet anywhere but at the corners (and the edge) they share.
bool piecesCross(Piece p, Piece q, const std::vector<Vec3>& xyz) {
  if (p.size < q.size) std::swap(p, q);
  const int shared = shareCorners(p, q);
  shareCorners(q, p);
  Vec3 a[3], b[3];
  for (int k = 0; k < p.size; ++k) a[k] = xyz[p.corners[k]];
  for (int k = 0; k < q.size; ++k) b[k] = xyz[q.corners[k]];
  if (shared == q.size && q.size < 3) return false;  // q is a corner or an edge of p
  if (p.size == 3 && q.size == 3) return trianglesCross(shared, a, b);
  if (p.size == 3 && q.size == 2)
    return shared == 0 ? segmentMeetsTriangle(b[0], b[1], a) : insideCorner(b[1], a);
  if (p.size == 3) return onTriangle(b[0], a);
  if (p.size == 2 && q.size == 2)
    return shared == 0 ? segmentsMeet(a[0], a[1], b[0], b[1])
                       : collinear(a[0], a[1], b[1]) && sameSide(a[0], a[1], b[1]);
  if (p.size == 2) return onSegment(b[0], a[0], a[1]);
  return a[0] == b[0];
}

// Candidate pairs come from a uniform grid of cells about the size of the pieces.
class PieceGrid {
 public:
  PieceGrid(const std::vector<Piece>& pieces, const std::vector<Vec3>& xyz);
  template <class Visit>
  void forCells(const BoundingBox& box, Visit visit) const;
  const std::vector<std::uint32_t>* cell(std::size_t key) const;  // null when empty
  BoundingBox boxOf(const Piece& p) const;

 private:
  std::array<std::size_t, 3> cellOf(Vec3 p) const;
  const std::vector<Vec3>& xyz_;
  BoundingBox all_;
  double cellSize_ = 1;
  std::array<std::size_t, 3> dims_{1, 1, 1};
  std::unordered_map<std::size_t, std::vector<std::uint32_t>> cells_;
};

BoundingBox PieceGrid::boxOf(const Piece& p) const {
  BoundingBox box;
  for (int k = 0; k < p.size; ++k) box.include(xyz_[p.corners[k]]);
  return box;
}

PieceGrid::PieceGrid(const std::vector<Piece>& pieces, const std::vector<Vec3>& xyz) : xyz_(xyz) {
  double sum = 0;
  for (const Piece& p : pieces) {
    const BoundingBox box = boxOf(p);
    all_.include(box);
    sum += distance(box.min, box.max);
  }
  const Vec3 extent = all_.max - all_.min;
  // About one piece per cell, and no more cells than a few per piece.
  cellSize_ = std::max({sum / static_cast<double>(pieces.size()), 1e-300,
                        std::cbrt(extent.x * extent.y * extent.z / (4.0 * pieces.size()))});
  dims_ = {static_cast<std::size_t>(extent.x / cellSize_) + 1,
           static_cast<std::size_t>(extent.y / cellSize_) + 1,
           static_cast<std::size_t>(extent.z / cellSize_) + 1};
  for (std::size_t i = 0; i < pieces.size(); ++i)
    forCells(boxOf(pieces[i]),
             [&](std::size_t key) { cells_[key].push_back(static_cast<std::uint32_t>(i)); });
}

std::array<std::size_t, 3> PieceGrid::cellOf(Vec3 p) const {
  auto index = [&](double x, double lo, std::size_t n) {
    return std::min(static_cast<std::size_t>(std::max(0.0, (x - lo) / cellSize_)), n - 1);
  };
  return {index(p.x, all_.min.x, dims_[0]), index(p.y, all_.min.y, dims_[1]),
          index(p.z, all_.min.z, dims_[2])};
}

template <class Visit>
void PieceGrid::forCells(const BoundingBox& box, Visit visit) const {
  const auto lo = cellOf(box.min), hi = cellOf(box.max);
  for (std::size_t i = lo[0]; i <= hi[0]; ++i)
    for (std::size_t j = lo[1]; j <= hi[1]; ++j)
      for (std::size_t k = lo[2]; k <= hi[2]; ++k) visit((i * dims_[1] + j) * dims_[2] + k);
}

const std::vector<std::uint32_t>* PieceGrid::cell(std::size_t key) const {
  auto it = cells_.find(key);
  return it == cells_.end() ? nullptr : &it->second;
}

bool boxesOverlap(const BoundingBox& a, const BoundingBox& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
         a.min.z <= b.max.z && b.min.z <= a.max.z;
}

// The triangles (shells first, then embedded surfaces), the segments, then the points.
std::vector<Piece> piecesOf(const VolumePlc& plc) {
  std::vector<Piece> pieces;
  for (const PlcTriangle& t : plc.triangles) pieces.push_back({t, 3});
  for (const PlcSegment& s : plc.segments) pieces.push_back({{s[0], s[1], -1}, 2});
  for (int p : plc.points) pieces.push_back({{p, -1, -1}, 1});
  return pieces;
}

std::string ownerOf(const VolumePlc& plc, std::size_t piece) {
  const std::size_t triangles = plc.triangles.size(), segments = plc.segments.size();
  if (piece < triangles)
    return (plc.isEmbedded(piece) ? "embedded surface " : "boundary surface ") +
           std::to_string(plc.surfaceOf[piece]);
  if (piece < triangles + segments)
    return "embedded curve " + std::to_string(plc.curveOf[piece - triangles]);
  return "embedded point " + std::to_string(plc.pointOf[piece - triangles - segments]);
}

// Piece i comes after piece j: when either is embedded, i is.
[[noreturn]] void reportCrossing(const ModelVolume& volume, const VolumePlc& plc,
                                 const std::vector<Piece>& pieces, std::size_t i, std::size_t j,
                                 const std::vector<Vec3>& xyz) {
  Vec3 at{};
  for (int k = 0; k < pieces[i].size; ++k) at = at + xyz[pieces[i].corners[k]];
  at = at / pieces[i].size;
  const std::string near = " near (" + std::to_string(at.x) + ", " + std::to_string(at.y) + ", " +
                           std::to_string(at.z) + ")";
  const EntityId id{3, volume.tag};
  if (i < plc.shellEnd)
    throw MeshError(id, "its boundary intersects itself: a triangle of surface " +
                            std::to_string(plc.surfaceOf[i]) + " crosses one of surface " +
                            std::to_string(plc.surfaceOf[j]) + near);
  const std::string first = ownerOf(plc, i), second = ownerOf(plc, j);
  if (first == second) throw MeshError(id, first + " intersects itself" + near);
  const char* meets =
      pieces[i].size == 1 ? (pieces[j].size == 1 ? " coincides with " : " lies on ") : " crosses ";
  throw MeshError(id, first + meets + second + near);
}

}  // namespace

void rejectIntersections(const ModelVolume& volume, const VolumePlc& plc,
                         const std::vector<Vec3>& xyz) {
  const std::vector<Piece> pieces = piecesOf(plc);
  const PieceGrid grid(pieces, xyz);
  std::vector<std::size_t> lastVisit(pieces.size(), SIZE_MAX);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const BoundingBox box = grid.boxOf(pieces[i]);
    grid.forCells(box, [&](std::size_t key) {
      const std::vector<std::uint32_t>* cell = grid.cell(key);
      for (std::uint32_t j : cell ? *cell : std::vector<std::uint32_t>{}) {
        if (j >= i || lastVisit[j] == i) continue;
        lastVisit[j] = i;
        if (boxesOverlap(box, grid.boxOf(pieces[j])) && piecesCross(pieces[i], pieces[j], xyz))
          reportCrossing(volume, plc, pieces, i, j, xyz);
      }
    });
  }
}

}  // namespace geomesh
