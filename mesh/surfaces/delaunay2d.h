#pragma once

#include <cstdint>
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
// to the constructor, so every inserted point lies strictly inside the hull.
class Triangulation2D {
 public:
  Triangulation2D(Vec2 boxMin, Vec2 boxMax);

  static constexpr std::uint32_t kFirstVertex = 3;  // vertices 0..2 are the enclosing ones

  std::uint32_t addPoint(Vec2 p);  // stores a point; insert() puts it in the triangulation
  void removeLastPoint();          // forgets the last point stored, if it was not inserted
  std::size_t pointCount() const { return points_.size(); }
  std::size_t triangleCount() const { return vertex_.size() / 3; }
  Vec2 point(std::uint32_t v) const { return points_[v]; }
  void movePoint(std::uint32_t v, Vec2 p) { points_[v] = p; }
  std::span<const Vec2> points() const { return points_; }

  std::uint32_t vertex(std::uint32_t corner) const { return vertex_[corner]; }
  std::uint32_t neighbour(std::uint32_t corner) const { return neighbour_[corner]; }
  EdgeKind kind(std::uint32_t corner) const { return kind_[corner]; }
  void setKind(std::uint32_t corner, EdgeKind k);  // both sides
  // Some triangle incident to v (kNone before v is inserted).
  std::uint32_t triangleOf(std::uint32_t v) const { return vertexTriangle_[v]; }
  bool hasEnclosingVertex(std::uint32_t t) const {
    return vertex_[3 * t] < kFirstVertex || vertex_[3 * t + 1] < kFirstVertex ||
           vertex_[3 * t + 2] < kFirstVertex;
  }

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

  // The corner, in a triangle incident to a, opposite the edge (a, b) with a before b in
  // counter-clockwise order; kNone if there is no such edge.
  std::uint32_t findEdge(std::uint32_t a, std::uint32_t b) const;
  // Replaces the two triangles sharing the edge of `corner` by the two on the other diagonal.
  void flip(std::uint32_t corner);
  // True if the edge of `corner` is free and not locally Delaunay.
  bool shouldFlip(std::uint32_t corner) const;
  // Lawson flips from the given corners until every free edge reached is locally Delaunay.
  void restoreDelaunay(std::vector<std::uint32_t> stack);

 private:
  void setTriangle(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c);
  void link(std::uint32_t c1, std::uint32_t c2, EdgeKind k);
  bool growCavity(std::uint32_t v, std::uint32_t containing, const MetricFrame* metric);
  bool inCircumcircle(std::uint32_t t, Vec2 p, const MetricFrame* metric) const;
  std::uint32_t nextRandom();

  std::vector<Vec2> points_;
  std::vector<std::uint32_t> vertex_;
  std::vector<std::uint32_t> neighbour_;
  std::vector<EdgeKind> kind_;
  std::vector<std::uint32_t> vertexTriangle_;
  std::vector<std::uint32_t> mark_;  // per triangle: cavity search stamps
  std::uint32_t epoch_ = 0;
  std::uint32_t random_ = 2463534242u;
  std::vector<std::uint32_t> cavity_, created_, rim_;
  std::vector<CavityEdge> rimEdges_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> fanIndex_;
};

// Delaunay triangulation of `points` (plus the three enclosing vertices) inserted in
// spatial order. Vertex k + kFirstVertex of the result is points[k]; a point equal to an
// earlier one is left out (triangleOf() is kNone for it).
Triangulation2D delaunayTriangulation(std::span<const Vec2> points);

}  // namespace geomesh
