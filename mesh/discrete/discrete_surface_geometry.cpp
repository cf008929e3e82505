// DiscreteSurfaceGeometry: uv point location (a walk from the last triangle found, a uniform
// grid, then CGAL's AABB tree for points outside every triangle) and closest points in space.
#include "mesh/discrete/discrete_surface_geometry.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <stdexcept>

namespace geomesh {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using CgalTriangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, CgalTriangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

// Barycentric coordinates of uv may fall this far below zero for uv still to count as inside:
// a point on an edge shared by two triangles belongs to both.
constexpr double kInside = -1e-12;
constexpr int kWalkSteps = 24;

// The affine map of one uv triangle: barycentric coordinates from uv, and its Jacobian.
struct TriangleMap {
  Vec2 origin;                      // uv of its vertex 0
  std::array<double, 4> inverse{};  // (s, t) = inverse * (uv - origin), row-major
  SurfaceDerivatives jacobian;      // d(xyz)/du, d(xyz)/dv
  bool degenerate = true;           // zero area in uv: holds no point
};

TriangleMap triangleMap(std::array<Vec2, 3> uv, std::array<Vec3, 3> xyz) {
  const double a = uv[1].u - uv[0].u, b = uv[2].u - uv[0].u;
  const double c = uv[1].v - uv[0].v, d = uv[2].v - uv[0].v;
  const double det = a * d - b * c;
  TriangleMap m;
  m.origin = uv[0];
  if (!(std::abs(det) > 0) || !std::isfinite(1 / det)) return m;
  m.inverse = {d / det, -b / det, -c / det, a / det};
  m.degenerate = false;
  const Vec3 e1 = xyz[1] - xyz[0], e2 = xyz[2] - xyz[0];
  m.jacobian = {m.inverse[0] * e1 + m.inverse[2] * e2, m.inverse[1] * e1 + m.inverse[3] * e2};
  return m;
}

std::array<double, 3> barycentric(const TriangleMap& m, Vec2 uv) {
  const double du = uv.u - m.origin.u, dv = uv.v - m.origin.v;
  const double s = m.inverse[0] * du + m.inverse[1] * dv;
  const double t = m.inverse[2] * du + m.inverse[3] * dv;
  return {1 - s - t, s, t};
}

bool inside(const std::array<double, 3>& b) {
  return b[0] >= kInside && b[1] >= kInside && b[2] >= kInside;
}

// Barycentric coordinates of the point q of a triangle in space (the least-squares ones when q
// is off its plane); those of its nearest vertex when the triangle is degenerate.
std::array<double, 3> barycentric(std::array<Vec3, 3> xyz, Vec3 q) {
  const Vec3 e1 = xyz[1] - xyz[0], e2 = xyz[2] - xyz[0], d = q - xyz[0];
  const double a = dot(e1, e1), b = dot(e1, e2), c = dot(e2, e2);
  const double det = a * c - b * b;
  if (det > 1e-24 * a * c && det > 0) {
    const double s = (c * dot(d, e1) - b * dot(d, e2)) / det;
    const double t = (a * dot(d, e2) - b * dot(d, e1)) / det;
    return {1 - s - t, s, t};
  }
  std::array<double, 3> nearest{};
  std::array<double, 3> gaps{distance(q, xyz[0]), distance(q, xyz[1]), distance(q, xyz[2])};
  nearest[std::min_element(gaps.begin(), gaps.end()) - gaps.begin()] = 1;
  return nearest;
}

// The coordinates clamped to the triangle, for values only known inside it.
std::array<double, 3> clamped(std::array<double, 3> b) {
  for (double& x : b) x = std::max(x, 0.0);
  const double sum = b[0] + b[1] + b[2];
  if (!(sum > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  return {b[0] / sum, b[1] / sum, b[2] / sum};
}

ParamBox uvBox(std::span<const Vec2> uv) {
  ParamBox box{{INFINITY, -INFINITY}, {INFINITY, -INFINITY}};
  for (Vec2 p : uv) {
    box.u = {std::min(box.u.min, p.u), std::max(box.u.max, p.u)};
    box.v = {std::min(box.v.min, p.v), std::max(box.v.max, p.v)};
  }
  return box;
}

// A uniform grid over the uv box; each cell lists the triangles whose boxes overlap it.
class UvGrid {
 public:
  UvGrid(const PatchMap& map, ParamBox box) : box_(box) {
    const double width = std::max(box.u.max - box.u.min, 1e-300);
    const double height = std::max(box.v.max - box.v.min, 1e-300);
    const double cells = std::max<double>(1, static_cast<double>(map.triangles.size()));
    const double side = std::sqrt(width * height / cells);
    columns_ = std::clamp(static_cast<int>(width / side), 1, 4096);
    rows_ = std::clamp(static_cast<int>(height / side), 1, 4096);
    cellWidth_ = width / columns_, cellHeight_ = height / rows_;
    fill(map);
  }

  // The triangles that may hold uv (none when uv is off the box).
  std::span<const std::uint32_t> candidates(Vec2 uv) const {
    if (uv.u < box_.u.min || uv.u > box_.u.max || uv.v < box_.v.min || uv.v > box_.v.max)
      return {};
    const std::size_t cell = static_cast<std::size_t>(row(uv.v)) * columns_ + column(uv.u);
    return std::span(triangles_).subspan(start_[cell], start_[cell + 1] - start_[cell]);
  }

 private:
  int column(double u) const {
    return std::clamp(static_cast<int>((u - box_.u.min) / cellWidth_), 0, columns_ - 1);
  }
  int row(double v) const {
    return std::clamp(static_cast<int>((v - box_.v.min) / cellHeight_), 0, rows_ - 1);
  }

  // Calls visit(cell) for every cell the triangle's box overlaps.
  template <typename Visit>
  void forCells(const PatchMap& map, const TriangleVertices& tri, Visit visit) const {
    const ParamBox b = uvBox(std::array{map.uv[tri[0]], map.uv[tri[1]], map.uv[tri[2]]});
    for (int j = row(b.v.min); j <= row(b.v.max); ++j)
      for (int i = column(b.u.min); i <= column(b.u.max); ++i)
        visit(static_cast<std::size_t>(j) * columns_ + i);
  }

  void fill(const PatchMap& map) {
    start_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
    for (const TriangleVertices& tri : map.triangles)
      forCells(map, tri, [&](std::size_t cell) { ++start_[cell + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    triangles_.resize(start_.back());
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    for (std::uint32_t k = 0; k < map.triangles.size(); ++k)
      forCells(map, map.triangles[k], [&](std::size_t cell) { triangles_[next[cell]++] = k; });
  }

  ParamBox box_;
  int columns_ = 1, rows_ = 1;
  double cellWidth_ = 1, cellHeight_ = 1;
  std::vector<std::size_t> start_;  // cell c lists triangles_[start_[c], start_[c + 1])
  std::vector<std::uint32_t> triangles_;
};

Kernel::Point_3 toCgal(Vec3 p) { return {p.x, p.y, p.z}; }

// A tree over the triangles, kept beside the triangles it points into. Built and given its
// search structure here, so that its const queries change nothing afterwards.
struct TriangleTree {
  explicit TriangleTree(CgalTriangles list) : triangles(std::move(list)) {
    tree.insert(triangles.begin(), triangles.end());
    tree.build();
    tree.accelerate_distance_queries();
  }
  std::uint32_t closest(Vec3 p, Vec3& at) const {
    const auto [point, id] = tree.closest_point_and_primitive(toCgal(p));
    at = {point.x(), point.y(), point.z()};
    return static_cast<std::uint32_t>(id - triangles.begin());
  }
  CgalTriangles triangles;
  Tree tree;
};

std::atomic<std::uint64_t> nextSearchId{1};

// The last triangle each thread found, and in which geometry.
struct LocationHint {
  std::uint64_t search = 0;
  std::uint32_t triangle = 0;
};
thread_local LocationHint hint;

}  // namespace

struct DiscreteSurfaceGeometry::Located {
  std::uint32_t triangle;
  std::array<double, 3> barycentric;  // of uv in it (outside it when uv is off every triangle)
};

struct DiscreteSurfaceGeometry::Search {
  Search(const PatchMap& map, std::span<const Vec3> points, ParamBox box)
      : neighbours(triangleAdjacency(map.triangles).neighbours),
        grid(map, box),
        inSpace(trianglesInSpace(map, points)),
        inPlane(trianglesInPlane(map)) {
    maps.reserve(map.triangles.size());
    for (const TriangleVertices& t : map.triangles)
      maps.push_back(triangleMap({map.uv[t[0]], map.uv[t[1]], map.uv[t[2]]},
                                 {points[t[0]], points[t[1]], points[t[2]]}));
  }

  static CgalTriangles trianglesInSpace(const PatchMap& map, std::span<const Vec3> points) {
    CgalTriangles list;
    for (const TriangleVertices& t : map.triangles)
      list.emplace_back(toCgal(points[t[0]]), toCgal(points[t[1]]), toCgal(points[t[2]]));
    return list;
  }
  static CgalTriangles trianglesInPlane(const PatchMap& map) {
    CgalTriangles list;
    auto at = [&](std::uint32_t v) { return Kernel::Point_3(map.uv[v].u, map.uv[v].v, 0); };
    for (const TriangleVertices& t : map.triangles)
      list.emplace_back(at(t[0]), at(t[1]), at(t[2]));
    return list;
  }

  // The walk towards uv from triangle `from`, across the edge facing the most negative
  // barycentric coordinate; nullopt when it leaves the patch or takes too long.
  std::optional<Located> walk(std::uint32_t from, Vec2 uv) const {
    std::uint32_t at = from;
    for (int step = 0; step < kWalkSteps && at != kNoTriangle; ++step) {
      const std::array<double, 3> b = barycentric(maps[at], uv);
      if (!maps[at].degenerate && inside(b)) return Located{at, b};
      const auto lowest = std::min_element(b.begin(), b.end()) - b.begin();
      at = neighbours[at][(lowest + 1) % 3];  // edge k runs from vertex k to k + 1
    }
    return std::nullopt;
  }

  std::optional<Located> fromGrid(Vec2 uv) const {
    for (std::uint32_t k : grid.candidates(uv)) {
      const std::array<double, 3> b = barycentric(maps[k], uv);
      if (!maps[k].degenerate && inside(b)) return Located{k, b};
    }
    return std::nullopt;
  }

  Located closestInPlane(Vec2 uv) const {
    Vec3 at;
    const std::uint32_t k = inPlane.closest({uv.u, uv.v, 0}, at);
    return {k, barycentric(maps[k], uv)};
  }

  std::uint64_t id = nextSearchId++;
  std::vector<TriangleMap> maps;
  std::vector<std::array<std::uint32_t, 3>> neighbours;
  UvGrid grid;
  TriangleTree inSpace, inPlane;
};

DiscreteSurfaceGeometry::DiscreteSurfaceGeometry(std::vector<Vec3> points, PatchMap map,
                                                 std::map<int, CurveTrace> curves,
                                                 std::vector<double> vertexCurvature)
    : points_(std::move(points)),
      map_(std::move(map)),
      curves_(std::move(curves)),
      vertexCurvature_(std::move(vertexCurvature)) {
  if (map_.triangles.empty()) throw std::invalid_argument("a discrete surface needs triangles");
  if (points_.size() != map_.uv.size() ||
      (!vertexCurvature_.empty() && vertexCurvature_.size() != map_.uv.size()))
    throw std::invalid_argument("a discrete surface needs one point and uv per vertex");
  for (const TriangleVertices& t : map_.triangles)
    if (std::max({t[0], t[1], t[2]}) >= points_.size())
      throw std::invalid_argument("a discrete surface's triangle has an unknown vertex");
  bounds_ = uvBox(map_.uv);
  search_ = std::make_unique<const Search>(map_, points_, bounds_);
}

DiscreteSurfaceGeometry::~DiscreteSurfaceGeometry() = default;

DiscreteSurfaceGeometry::Located DiscreteSurfaceGeometry::locate(Vec2 uv) const {
  const Search& s = *search_;
  if (!std::isfinite(uv.u) || !std::isfinite(uv.v)) return {0, barycentric(s.maps[0], uv)};
  const std::uint32_t from = hint.search == s.id ? hint.triangle : 0;
  std::optional<Located> found = s.walk(from, uv);
  if (!found) found = s.fromGrid(uv);
  if (!found) found = s.closestInPlane(uv);
  hint = {s.id, found->triangle};
  return *found;
}

Vec3 DiscreteSurfaceGeometry::point(Vec2 uv) const {
  // A plane patch is its plane: no triangle to find.
  if (hasPlaneFrame()) return map_.origin + uv.u * map_.axisU + uv.v * map_.axisV;
  const Located at = locate(uv);
  const TriangleVertices& t = map_.triangles[at.triangle];
  const std::array<double, 3>& b = at.barycentric;
  return b[0] * points_[t[0]] + b[1] * points_[t[1]] + b[2] * points_[t[2]];
}

SurfaceDerivatives DiscreteSurfaceGeometry::firstDerivatives(Vec2 uv) const {
  if (hasPlaneFrame()) return {map_.axisU, map_.axisV};
  return search_->maps[locate(uv).triangle].jacobian;
}

Vec2 DiscreteSurfaceGeometry::project(Vec3 p) const {
  Vec3 closest;
  const std::uint32_t k = search_->inSpace.closest(p, closest);
  const TriangleVertices& t = map_.triangles[k];
  const std::array<double, 3> b =
      clamped(barycentric({points_[t[0]], points_[t[1]], points_[t[2]]}, closest));
  const Vec2 a = map_.uv[t[0]], c = map_.uv[t[1]], d = map_.uv[t[2]];
  return {b[0] * a.u + b[1] * c.u + b[2] * d.u, b[0] * a.v + b[1] * c.v + b[2] * d.v};
}

std::uint32_t DiscreteSurfaceGeometry::closestTriangle(Vec3 p) const {
  Vec3 closest;
  return search_->inSpace.closest(p, closest);
}

std::optional<Vec2> DiscreteSurfaceGeometry::curveParameters(int signedCurve, double t) const {
  const auto it = curves_.find(std::abs(signedCurve));
  if (it == curves_.end()) return std::nullopt;
  const CurveTrace& trace = it->second;
  if (trace.t.empty() || trace.t.size() != trace.uv.size()) return std::nullopt;
  if (t <= trace.t.front()) return trace.uv.front();
  if (t >= trace.t.back()) return trace.uv.back();
  const auto k = static_cast<std::size_t>(
      std::upper_bound(trace.t.begin(), trace.t.end(), t) - trace.t.begin());
  const double span = trace.t[k] - trace.t[k - 1];
  const double w = span > 0 ? (t - trace.t[k - 1]) / span : 0;
  const Vec2 a = trace.uv[k - 1], b = trace.uv[k];
  return Vec2{a.u + w * (b.u - a.u), a.v + w * (b.v - a.v)};
}

std::optional<double> DiscreteSurfaceGeometry::curvature(Vec2 uv) const {
  if (vertexCurvature_.empty()) return std::nullopt;
  const Located at = locate(uv);
  const TriangleVertices& t = map_.triangles[at.triangle];
  const std::array<double, 3> b = clamped(at.barycentric);
  return b[0] * vertexCurvature_[t[0]] + b[1] * vertexCurvature_[t[1]] +
         b[2] * vertexCurvature_[t[2]];
}

}  // namespace geomesh
