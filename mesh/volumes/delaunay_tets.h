// DelaunayTets: a tetrahedralization in flat arrays with Bowyer-Watson point insertion.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec3.h"

namespace geomesh {

inline constexpr std::uint32_t kNoTet = 0xffffffffu;

// One key for the edge between two vertices, whichever comes first.
inline std::uint64_t vertexPairKey(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
}

// Tetrahedra as flat arrays: 4 vertex indices and 4 neighbour links per tetrahedron, no heap
// object per tetrahedron. Vertices (v0, v1, v2, v3) are positively oriented (orient3d > 0).
// Face f is the face opposite vertex f; neighbours[4t + f] is 4n + g when face g of n is the
// same face, kNoTet on the domain's boundary. A face may be constrained: the mesh keeps it
// (a boundary facet or an embedded one), insertion neither removes nor crosses it. Deleted
// tetrahedra are kept as free slots and reused.
class DelaunayTets {
 public:
  // The vertex indices of face f of a tetrahedron, ordered so that they turn counter-clockwise
  // seen from the vertex opposite (orient3d(face, v_f) > 0).
  static constexpr int kFace[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

  std::vector<Vec3> points;
  std::vector<std::uint32_t> vertices;    // 4 per tetrahedron
  std::vector<std::uint32_t> neighbours;  // 4 per tetrahedron (half-face links)
  std::vector<std::uint8_t> flags;        // per tetrahedron: bit f = face f constrained, marks

  std::size_t slotCount() const { return flags.size(); }
  bool alive(std::uint32_t t) const { return !(flags[t] & kDeleted); }
  bool constrained(std::uint32_t t, int f) const { return (flags[t] >> f) & 1; }
  std::size_t tetCount() const { return slotCount() - free_.size(); }

  // The Delaunay tetrahedralization of the points, inserted in a BRIO order along a Hilbert
  // curve inside an enclosing tetrahedron whose corners are removed at the end with the
  // tetrahedra that use them (what is left is the tetrahedra of the points whose circumsphere
  // holds none of the points; all of them when the points are in general position, except
  // near the convex hull where an enclosing corner was closer). Duplicate points are skipped.
  static DelaunayTets build(std::span<const Vec3> points);

  // A mesh from given tetrahedra (each positively oriented), neighbours found here; faces in
  // one tetrahedron only become constrained, as do the listed faces (sorted or not).
  static DelaunayTets fromTetrahedra(std::vector<Vec3> points, std::vector<std::uint32_t> tets,
                                     std::span<const std::array<std::uint32_t, 3>> keptFaces);

  enum class Insertion : std::uint8_t {
    kInserted,
    kOutside,     // the walk met the boundary (or a constrained face) before the point
    kTooClose,    // a vertex of the cavity is nearer than the distance asked for
    kDegenerate,  // the cavity cannot be re-filled from the point (not star-shaped)
    kKeptEdge,    // the insertion would remove a kept edge
  };

  // Locates the point by a visibility walk from `start` (an alive tetrahedron): the
  // tetrahedron that contains it, or kNoTet when the walk leaves the domain or crosses a
  // constrained face. `barycentric` receives its coordinates in that tetrahedron.
  std::uint32_t locate(Vec3 p, std::uint32_t start, double barycentric[4] = nullptr) const;

  // Inserts p (Bowyer-Watson): the cavity of the tetrahedra whose circumsphere holds p, grown
  // from the one containing it and stopped at constrained faces, replaced by the tetrahedra
  // joining p to its boundary. With minDistance > 0, a point nearer than that to a vertex of
  // the cavity is refused. On insertion the new vertex is points.size() - 1.
  Insertion insert(Vec3 p, std::uint32_t start, double minDistance = 0);
  // The same for a vertex already in `points` (not yet in any tetrahedron).
  Insertion insertVertex(std::uint32_t v, std::uint32_t start, double minDistance = 0);

  // Marks the edges that insertion must keep (an edge whose every tetrahedron would fall in a
  // cavity is refused). Vertex pairs, any order.
  void keepEdges(std::span<const std::array<std::uint32_t, 2>> edges);

  // New tetrahedra whose height over the face opposite the new vertex is under this fraction
  // of the face's longest edge are not made: their tetrahedron leaves the cavity (which may
  // then refuse the point as degenerate). 0 (the default) keeps the Delaunay cavities whole.
  void refuseFlat(double minHeight) { minHeight_ = minHeight; }

  // The alive tetrahedra, 4 vertices each.
  std::vector<std::uint32_t> liveTetrahedra() const;

  // A tetrahedron created by the last successful insertion (or any alive one).
  std::uint32_t lastTet() const { return last_; }
  // The tetrahedra the last successful insertion created.
  std::span<const std::uint32_t> created() const { return created_; }

 private:
  static constexpr std::uint8_t kDeleted = 0x80;
  static constexpr std::uint8_t kInCavity = 0x20;  // scratch marks of insert()
  static constexpr std::uint8_t kReached = 0x40;
  bool inCavity(std::uint32_t t) const { return flags[t] & kInCavity; }

  std::uint32_t newSlot();
  bool removesKeptEdge(std::span<const std::uint32_t> cavity) const;
  // Vertices inserted after keepEdges are on no kept edge.
  bool isKeptVertex(std::uint32_t v) const { return v < keptVertex_.size() && keptVertex_[v]; }
  bool shapeCavity(Vec3 p, std::uint32_t t0);

  std::vector<std::uint32_t> free_;
  std::uint32_t last_ = 0;
  double minHeight_ = 0;
  // Scratch of insert(), kept to avoid allocations.
  std::vector<std::uint32_t> cavity_, boundary_, created_, outside_;
  std::vector<std::uint64_t> hashKeys_;
  std::vector<std::uint32_t> hashValues_;
  std::vector<std::uint8_t> keptVertex_;
  std::vector<std::uint64_t> keptEdges_;  // sorted vertex-pair keys
};

}  // namespace geomesh
