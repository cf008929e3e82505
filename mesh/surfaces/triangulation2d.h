// Triangulation2D: a planar triangulation in flat corner arrays, with its local operations.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/surfaces/surface_metric.h"

namespace geomesh {

inline constexpr std::uint32_t kNone = 0xffffffffu;

// Kind of a triangulation edge: free edges may be flipped or crossed by cavities; boundary
// edges separate the domain from the outside (and holes); embedded edges are kept but do not
// change the side.
enum class EdgeKind : std::uint8_t { Free = 0, Boundary = 1, Embedded = 2 };

// A 2D triangulation stored as flat arrays. Triangle t has vertices vertex[3t..3t+2] in
// counter-clockwise order; "corner" 3t+i names vertex i of t and the edge opposite it.
// neighbour[c] is the corner of the adjacent triangle opposite the same edge (kNone on the
// hull), and kind[c] the edge's kind (equal on both sides).
//
// The triangulation starts as one large triangle (vertices 0, 1, 2) enclosing the box given
// to the constructor, so every inserted point lies strictly inside the hull. Delaunay
// insertion (delaunay2d.cpp) grows it; keepTriangles() cuts it down to a domain, whose
// boundary edges then lie on the hull, for the local modifications of mesh adaptation
// (split, flip, collapse). A collapse leaves dead triangles (alive() false), which later
// triangles reuse. Callers check validity (orientation, link condition) before modifying.
class Triangulation2D {
 public:
  Triangulation2D(Vec2 boxMin, Vec2 boxMax);

  static constexpr std::uint32_t kFirstVertex = 3;  // vertices 0..2 are the enclosing ones
  static constexpr std::uint32_t nextCorner(std::uint32_t c) { return c % 3 == 2 ? c - 2 : c + 1; }
  static constexpr std::uint32_t prevCorner(std::uint32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }

  std::uint32_t addPoint(Vec2 p);  // stores a point; insert() or split() puts it in
  void removeLastPoint();          // forgets the last point stored, if it was not inserted
  std::size_t pointCount() const { return points_.size(); }
  // The target size at each point, which refinement extends inwards from the boundary (0
  // until set): one value per point, stored beside the coordinates.
  double size(std::uint32_t v) const { return sizes_[v]; }
  void setSize(std::uint32_t v, double size) { sizes_[v] = size; }
  std::span<const double> sizes() const { return sizes_; }
  std::size_t triangleCount() const { return vertex_.size() / 3; }  // dead ones included
  bool alive(std::uint32_t t) const { return alive_[t] != 0; }
  Vec2 point(std::uint32_t v) const { return points_[v]; }
  void movePoint(std::uint32_t v, Vec2 p) { points_[v] = p; }
  std::span<const Vec2> points() const { return points_; }

  std::uint32_t vertex(std::uint32_t corner) const { return vertex_[corner]; }
  std::uint32_t neighbour(std::uint32_t corner) const { return neighbour_[corner]; }
  EdgeKind kind(std::uint32_t corner) const { return kind_[corner]; }
  void setKind(std::uint32_t corner, EdgeKind k);  // both sides
  // Some triangle incident to v (kNone before v is inserted, or once it is removed).
  std::uint32_t triangleOf(std::uint32_t v) const { return vertexTriangle_[v]; }
  bool inMesh(std::uint32_t v) const { return vertexTriangle_[v] != kNone; }
  bool hasEnclosingVertex(std::uint32_t t) const {
    return vertex_[3 * t] < kFirstVertex || vertex_[3 * t + 1] < kFirstVertex ||
           vertex_[3 * t + 2] < kFirstVertex;
  }

  // --- Adjacency queries (triangulation2d.cpp)
  // The corner, in a triangle incident to a, opposite the edge (a, b) with a before b in
  // counter-clockwise order; kNone if there is no such edge.
  std::uint32_t findEdge(std::uint32_t a, std::uint32_t b) const;
  // A corner opposite the edge {a, b} in either direction: in the first triangle of a's ring
  // (see ring) that has it; kNone if there is none.
  std::uint32_t findUndirectedEdge(std::uint32_t a, std::uint32_t b) const;
  // The corners of v in its triangles, counter-clockwise around v. Returns false when v is
  // on the hull; the first triangle is then the one after the hull edge.
  bool ring(std::uint32_t v, std::vector<std::uint32_t>& corners) const;

  // --- Local operations (triangulation2d.cpp)
  // Replaces the two triangles sharing the edge of `corner` by the two on the other diagonal.
  void flip(std::uint32_t corner);
  // Splits the edge of `corner`, shared by two triangles, at vertex m: they become four.
  void split(std::uint32_t corner, std::uint32_t m);
  // Removes vertex v, not on the hull, whose counter-clockwise corners are `ringOfV`, by
  // merging it into its neighbour w; the two triangles of edge (v, w) die.
  void collapse(std::uint32_t v, std::uint32_t w, const std::vector<std::uint32_t>& ringOfV);
  // Keeps only the triangles flagged in `keep` (renumbered in order): edges shared with the
  // others go on the hull, vertices left without a triangle leave the mesh.
  void keepTriangles(const std::vector<std::uint8_t>& keep);
  // Flips from the given corners while shouldFlip(corner) holds for an edge reached, at most
  // `budget` times: after a flip, the four outer edges of its two triangles are looked at.
  template <class ShouldFlip>
  void flipWhile(std::vector<std::uint32_t> stack, ShouldFlip shouldFlip,
                 std::size_t budget = std::numeric_limits<std::size_t>::max());

  // --- Delaunay (delaunay2d.cpp)
  // The triangle containing p (on its boundary possibly), found by a walk from `start`.
  std::uint32_t locate(Vec2 p, std::uint32_t start);

  enum class InsertStatus { Inserted, Duplicate, Rejected };
  // Inserts point v, found in triangle `containing` (from locate), by Bowyer-Watson: the
  // cavity of triangles whose circumcircle holds the point, grown without crossing non-free
  // edges, is replaced by a fan around v. Rejected when v lies on a non-free edge.
  InsertStatus insert(std::uint32_t v, std::uint32_t containing);
  // The same in two steps: findCavity() changes nothing, so the caller may look at the
  // boundary of the cavity, whose vertices become v's neighbours, before commitCavity() or
  // giving up. With a metric frame, circumcircles are taken after mapping the points by it
  // (an anisotropic Delaunay kernel, for curved surfaces); Rejected if that cavity is not
  // star-shaped around v.
  InsertStatus findCavity(std::uint32_t v, std::uint32_t containing,
                          const MetricFrame* metric = nullptr);
  struct CavityEdge {
    std::uint32_t a, b;     // counter-clockwise seen from inside the cavity
    std::uint32_t outside;  // corner across it, or kNone
    EdgeKind kind;
  };
  std::span<const CavityEdge> cavityBoundary() const { return rimEdges_; }
  void commitCavity(std::uint32_t v);
  // Triangles created (or reused) by the last insertion.
  std::span<const std::uint32_t> created() const { return created_; }
  // Corners of the triangles outside the last cavity that face it (in created() order).
  std::span<const std::uint32_t> cavityRim() const { return rim_; }

  // True if the edge of `corner` is free and not locally Delaunay.
  bool shouldFlip(std::uint32_t corner) const;
  // Lawson flips from the given corners until every free edge reached is locally Delaunay.
  void restoreDelaunay(std::vector<std::uint32_t> stack);

 private:
  std::uint32_t cornerOf(std::uint32_t t, std::uint32_t v) const {
    return 3 * t + (vertex_[3 * t] == v ? 0 : vertex_[3 * t + 1] == v ? 1 : 2);
  }
  std::uint32_t newTriangle();
  void setTriangle(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c);
  void link(std::uint32_t c1, std::uint32_t c2, EdgeKind k);
  bool growCavity(std::uint32_t v, std::uint32_t containing, const MetricFrame* metric);
  bool inCircumcircle(std::uint32_t t, Vec2 p, const MetricFrame* metric) const;
  std::uint32_t nextRandom();

  std::vector<Vec2> points_;
  std::vector<double> sizes_;                  // per vertex: target size
  std::vector<std::uint32_t> vertexTriangle_;  // per vertex: a triangle around it, or kNone
  std::vector<std::uint32_t> vertex_, neighbour_;  // per corner
  std::vector<EdgeKind> kind_;                     // per corner
  std::vector<std::uint8_t> alive_;                // per triangle
  std::vector<std::uint32_t> mark_;                // per triangle: cavity search stamps
  std::vector<std::uint32_t> dead_;                // triangles to reuse
  std::uint32_t epoch_ = 0;
  std::uint32_t random_ = 2463534242u;
  std::vector<std::uint32_t> cavity_, created_, rim_;
  std::vector<CavityEdge> rimEdges_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> fanIndex_;
  mutable std::vector<std::uint32_t> scratch_;
};

template <class ShouldFlip>
void Triangulation2D::flipWhile(std::vector<std::uint32_t> stack, ShouldFlip shouldFlip,
                                std::size_t budget) {
  while (!stack.empty() && budget > 0) {
    const std::uint32_t c = stack.back();
    stack.pop_back();
    if (!shouldFlip(c)) continue;
    const std::uint32_t c2 = neighbour_[c];
    flip(c);
    --budget;
    const std::uint32_t t = c / 3, t2 = c2 / 3;
    stack.insert(stack.end(), {3 * t, 3 * t + 2, 3 * t2, 3 * t2 + 2});
  }
}

}  // namespace geomesh
