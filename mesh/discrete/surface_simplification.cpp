// Quadric-error edge collapses (Garland and Heckbert 1997): each vertex carries the quadric of
// the planes of its original triangles; the edge whose merged quadric is smallest at its best
// position collapses first, unless that would fold or pinch the surface.
#include "mesh/discrete/surface_simplification.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <queue>

#include "mesh/discrete/surface_topology.h"

namespace geomesh {
namespace {

constexpr double kSingular = 1e-10;        // |det A| relative to trace(A)^3
constexpr double kBoundaryWeight = 1e3;    // of a boundary edge's plane against a triangle's
constexpr double kFarthestPlacement = 2;  // in edge lengths from the midpoint

// The sum of squared distances to weighted planes n.x + d = 0, as x^T A x + 2 b.x + c.
struct Quadric {
  double a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0;
  double b0 = 0, b1 = 0, b2 = 0, c = 0;

  static Quadric plane(Vec3 n, double d, double weight) {
    const double w = weight;
    return {w * n.x * n.x, w * n.x * n.y, w * n.x * n.z, w * n.y * n.y, w * n.y * n.z,
            w * n.z * n.z, w * d * n.x,   w * d * n.y,   w * d * n.z,   w * d * d};
  }
  Quadric& operator+=(const Quadric& q) {
    a00 += q.a00, a01 += q.a01, a02 += q.a02, a11 += q.a11, a12 += q.a12, a22 += q.a22;
    b0 += q.b0, b1 += q.b1, b2 += q.b2, c += q.c;
    return *this;
  }
  double error(Vec3 p) const {
    const Vec3 ap{a00 * p.x + a01 * p.y + a02 * p.z, a01 * p.x + a11 * p.y + a12 * p.z,
                  a02 * p.x + a12 * p.y + a22 * p.z};
    return std::max(0.0, dot(p, ap) + 2 * (b0 * p.x + b1 * p.y + b2 * p.z) + c);
  }
  // The solution of A x = -b by cofactors, none when A is (nearly) singular.
  std::optional<Vec3> minimizer() const {
    const double c00 = a11 * a22 - a12 * a12, c01 = a02 * a12 - a01 * a22,
                 c02 = a01 * a12 - a02 * a11, c11 = a00 * a22 - a02 * a02,
                 c12 = a01 * a02 - a00 * a12, c22 = a00 * a11 - a01 * a01;
    const double det = a00 * c00 + a01 * c01 + a02 * c02, trace = a00 + a11 + a22;
    if (!(std::abs(det) > kSingular * trace * trace * trace)) return std::nullopt;
    return Vec3{c00 * b0 + c01 * b1 + c02 * b2, c01 * b0 + c11 * b1 + c12 * b2,
                c02 * b0 + c12 * b1 + c22 * b2} /
           -det;
  }
};

Vec3 bestPlacement(const Quadric& q, Vec3 a, Vec3 b) {
  const Vec3 middle = 0.5 * (a + b);
  const std::optional<Vec3> optimum = q.minimizer();
  if (optimum && distance(*optimum, middle) <= kFarthestPlacement * distance(a, b)) return *optimum;
  Vec3 best = middle;
  for (Vec3 p : {a, b})
    if (q.error(p) < q.error(best)) best = p;
  return best;
}

// Merging `remove` into `keep`, moved to `position`, as evaluated when the vertices had the
// given stamps.
struct Candidate {
  double cost;
  std::uint32_t keep, remove, keepStamp, removeStamp;
  Vec3 position;
  friend bool operator>(const Candidate& x, const Candidate& y) { return x.cost > y.cost; }
};

class EdgeCollapser {
 public:
  EdgeCollapser(const Triangulation& t, bool keepBoundary);
  void run(const SimplifyOptions& options);
  Triangulation result() const;

 private:
  void addPlaneQuadrics(bool keepBoundary);
  void pushEdge(std::uint32_t a, std::uint32_t b);
  const std::vector<std::uint32_t>& liveTriangles(std::uint32_t v);
  std::vector<std::uint32_t> neighbours(std::uint32_t v);
  bool isCurrent(const Candidate& c) const;
  bool keepsManifold(std::uint32_t keep, std::uint32_t remove);
  bool keepsOrientation(std::uint32_t moved, std::uint32_t other, Vec3 position);
  void collapse(const Candidate& c);

  std::vector<Vec3> points_;
  std::vector<TriangleVertices> triangles_;
  std::vector<bool> alive_;
  std::vector<std::vector<std::uint32_t>> around_;  // triangles per vertex (some may be dead)
  std::vector<Quadric> quadrics_;
  std::vector<std::uint32_t> stamp_;  // bumped whenever a vertex moves
  std::vector<bool> locked_, onBoundary_, removed_;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> queue_;
  std::size_t aliveCount_ = 0;
};

bool contains(const TriangleVertices& v, std::uint32_t vertex) {
  return v[0] == vertex || v[1] == vertex || v[2] == vertex;
}

EdgeCollapser::EdgeCollapser(const Triangulation& t, bool keepBoundary)
    : points_(t.points),
      around_(t.points.size()),
      quadrics_(t.points.size()),
      stamp_(t.points.size(), 0),
      removed_(t.points.size(), false) {
  for (const TriangleVertices& v : t.triangles)
    if (v[0] != v[1] && v[1] != v[2] && v[2] != v[0]) triangles_.push_back(v);
  alive_.assign(triangles_.size(), true);
  aliveCount_ = triangles_.size();
  for (std::uint32_t tri = 0; tri < triangles_.size(); ++tri)
    for (std::uint32_t v : triangles_[tri]) around_[v].push_back(tri);
  onBoundary_ = boundaryVertices({points_, triangles_});
  locked_.assign(points_.size(), false);
  if (keepBoundary) locked_ = onBoundary_;
  for (const auto& [a, b] : triangleAdjacency(triangles_).nonManifoldEdges)
    locked_[a] = locked_[b] = true;
  addPlaneQuadrics(keepBoundary);

  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * triangles_.size());
  for (const TriangleVertices& v : triangles_)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) pushEdge(a, b);
}

void EdgeCollapser::addPlaneQuadrics(bool keepBoundary) {
  const Triangulation surface{points_, triangles_};
  const TriangleAdjacency adjacency = triangleAdjacency(triangles_);
  for (std::uint32_t tri = 0; tri < triangles_.size(); ++tri) {
    const TriangleVertices& v = triangles_[tri];
    const Vec3 n = triangleNormal(surface, tri);
    if (n == Vec3{}) continue;
    const Quadric q = Quadric::plane(n, -dot(n, points_[v[0]]), 1);
    for (std::uint32_t k : v) quadrics_[k] += q;
    if (keepBoundary) continue;
    // A boundary edge keeps its place through a plane perpendicular to its triangle.
    for (int k = 0; k < 3; ++k) {
      if (adjacency.neighbours[tri][k] != kNoTriangle) continue;
      const Vec3 a = points_[v[k]], b = points_[v[(k + 1) % 3]];
      const Vec3 m = normalized(cross(b - a, n));
      const Quadric side = Quadric::plane(m, -dot(m, a), kBoundaryWeight);
      quadrics_[v[k]] += side, quadrics_[v[(k + 1) % 3]] += side;
    }
  }
}

void EdgeCollapser::pushEdge(std::uint32_t a, std::uint32_t b) {
  if (locked_[a] && locked_[b]) return;
  const std::uint32_t keep = locked_[b] ? b : a, remove = keep == a ? b : a;
  Quadric q = quadrics_[a];
  q += quadrics_[b];
  const Vec3 p = locked_[keep] ? points_[keep] : bestPlacement(q, points_[a], points_[b]);
  queue_.push({q.error(p), keep, remove, stamp_[keep], stamp_[remove], p});
}

const std::vector<std::uint32_t>& EdgeCollapser::liveTriangles(std::uint32_t v) {
  std::erase_if(around_[v], [&](std::uint32_t tri) { return !alive_[tri]; });
  return around_[v];
}

std::vector<std::uint32_t> EdgeCollapser::neighbours(std::uint32_t v) {
  std::vector<std::uint32_t> ring;
  for (std::uint32_t tri : liveTriangles(v))
    for (std::uint32_t w : triangles_[tri])
      if (w != v) ring.push_back(w);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  return ring;
}

bool EdgeCollapser::isCurrent(const Candidate& c) const {
  return !removed_[c.keep] && !removed_[c.remove] && stamp_[c.keep] == c.keepStamp &&
         stamp_[c.remove] == c.removeStamp;
}

// The link condition: the vertices adjacent to both ends are exactly the apexes of the edge's
// triangles, and no triangle of `remove` becomes a copy of one of `keep`'s (a tetrahedron
// would fold flat). An interior edge between two boundary vertices would pinch the surface.
bool EdgeCollapser::keepsManifold(std::uint32_t keep, std::uint32_t remove) {
  std::size_t shared = 0;
  for (std::uint32_t tri : liveTriangles(remove)) shared += contains(triangles_[tri], keep);
  if (shared == 0 || shared > 2) return false;
  if (shared == 2 && onBoundary_[keep] && onBoundary_[remove]) return false;
  const std::vector<std::uint32_t> a = neighbours(keep), b = neighbours(remove);
  std::vector<std::uint32_t> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  if (common.size() != shared) return false;
  for (std::uint32_t tri : liveTriangles(remove)) {
    const TriangleVertices& v = triangles_[tri];
    if (contains(v, keep)) continue;
    for (std::uint32_t other : liveTriangles(keep)) {
      const TriangleVertices& w = triangles_[other];
      if (std::all_of(v.begin(), v.end(),
                      [&](std::uint32_t x) { return x == remove || contains(w, x); }))
        return false;
    }
  }
  return true;
}

bool EdgeCollapser::keepsOrientation(std::uint32_t moved, std::uint32_t other, Vec3 position) {
  for (std::uint32_t tri : liveTriangles(moved)) {
    const TriangleVertices& v = triangles_[tri];
    if (contains(v, other)) continue;
    std::array<Vec3, 3> p{points_[v[0]], points_[v[1]], points_[v[2]]};
    const Vec3 before = cross(p[1] - p[0], p[2] - p[0]);
    for (int k = 0; k < 3; ++k)
      if (v[k] == moved) p[k] = position;
    const Vec3 after = cross(p[1] - p[0], p[2] - p[0]);
    if (after == Vec3{} || dot(before, after) < 0) return false;
  }
  return true;
}

void EdgeCollapser::collapse(const Candidate& c) {
  points_[c.keep] = c.position;
  quadrics_[c.keep] += quadrics_[c.remove];
  onBoundary_[c.keep] = onBoundary_[c.keep] || onBoundary_[c.remove];
  removed_[c.remove] = true;
  ++stamp_[c.keep];
  for (std::uint32_t tri : liveTriangles(c.remove)) {
    TriangleVertices& v = triangles_[tri];
    if (contains(v, c.keep)) {
      alive_[tri] = false;
      --aliveCount_;
      continue;
    }
    std::replace(v.begin(), v.end(), c.remove, c.keep);
    around_[c.keep].push_back(tri);
  }
  around_[c.remove] = {};
  for (std::uint32_t w : neighbours(c.keep)) pushEdge(c.keep, w);
}

void EdgeCollapser::run(const SimplifyOptions& options) {
  if (options.targetTriangles == 0 && options.maxError <= 0) return;
  while (!queue_.empty()) {
    if (options.targetTriangles > 0 && aliveCount_ <= options.targetTriangles) break;
    const Candidate c = queue_.top();
    queue_.pop();
    if (!isCurrent(c)) continue;
    if (options.maxError > 0 && c.cost > options.maxError) break;
    if (keepsManifold(c.keep, c.remove) && keepsOrientation(c.remove, c.keep, c.position) &&
        keepsOrientation(c.keep, c.remove, c.position))
      collapse(c);
  }
}

Triangulation EdgeCollapser::result() const {
  Triangulation out;
  constexpr std::uint32_t kUnnumbered = 0xffffffffu;
  std::vector<std::uint32_t> renumbered(points_.size(), kUnnumbered);
  for (std::uint32_t tri = 0; tri < triangles_.size(); ++tri) {
    if (!alive_[tri]) continue;
    TriangleVertices& v = out.triangles.emplace_back(triangles_[tri]);
    for (std::uint32_t& k : v) {
      if (renumbered[k] == kUnnumbered) {
        renumbered[k] = static_cast<std::uint32_t>(out.points.size());
        out.points.push_back(points_[k]);
      }
      k = renumbered[k];
    }
  }
  return out;
}

}  // namespace

Triangulation simplify(const Triangulation& t, const SimplifyOptions& options) {
  EdgeCollapser collapser(t, options.keepBoundary);
  collapser.run(options);
  return collapser.result();
}

}  // namespace geomesh
