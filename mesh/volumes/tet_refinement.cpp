// refineToSizes: rounds of circumcentre insertion, Hilbert-sorted, refused by spacing.
#include "mesh/volumes/tet_refinement.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mesh/core/quality.h"
#include "mesh/core/spatial_sort.h"

namespace geomesh {

namespace {

// A tetrahedron is refined while its circumradius exceeds this fraction of the local size
// (the circumradius of a regular tetrahedron is 0.61 times its edge), and a new point is
// refused nearer than kSpacing times the size to an existing vertex. Together they set the
// density: these values give the node counts of the reference's Delaunay mesher (within a
// few percent on boxes, spheres and parts with size fields).
constexpr double kRadiusRatio = 1.05;
constexpr double kSpacing = 0.8;
constexpr int kMaxRounds = 200;

struct Candidate {
  Vec3 point;
  std::uint32_t tet;
  double size;  // the mean size at the generator's vertices
};

// Keeps, of candidates met in order, those farther than kSpacing times their size from every
// candidate kept before at about the same size: a hash grid per power of two of the size,
// whose cells are twice that power, so that only the 27 cells around a point are looked at
// (its own first, where a refusal is most often found). Candidates of quite different sizes
// are left for the insertion to compare.
class CandidateFilter {
 public:
  // Ready for at most `count` candidates.
  void reset(std::size_t count) {
    keys_.assign(std::bit_ceil(2 * count + 16), kEmpty);
    heads_.resize(keys_.size());
    kept_.clear();
    next_.clear();
  }

  bool keep(Vec3 p, double size) {
    const int level = static_cast<int>(std::floor(std::log2(size)));
    const double cell = std::ldexp(2.0, level);
    const auto ix = static_cast<std::int64_t>(std::floor(p.x / cell));
    const auto iy = static_cast<std::int64_t>(std::floor(p.y / cell));
    const auto iz = static_cast<std::int64_t>(std::floor(p.z / cell));
    const double limit = kSpacing * size * kSpacing * size;
    auto near = [&](std::uint64_t k) {
      const std::size_t slot = find(k);
      if (keys_[slot] == kEmpty) return false;
      for (std::uint32_t i = heads_[slot]; i != kNone; i = next_[i]) {
        const Vec3 d = kept_[i] - p;
        if (dot(d, d) < limit) return true;
      }
      return false;
    };
    const std::uint64_t own = key(level, ix, iy, iz);
    if (near(own)) return false;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz)
          if ((dx || dy || dz) && near(key(level, ix + dx, iy + dy, iz + dz))) return false;
    const auto index = static_cast<std::uint32_t>(kept_.size());
    kept_.push_back(p);
    const std::size_t slot = find(own);
    next_.push_back(keys_[slot] == kEmpty ? kNone : heads_[slot]);
    keys_[slot] = own;
    heads_[slot] = index;
    return true;
  }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  static std::uint64_t key(int level, std::int64_t x, std::int64_t y, std::int64_t z) {
    const auto m = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0xfffffu; };
    return (static_cast<std::uint64_t>(level & 0xf) << 60) | (m(x) << 40) | (m(y) << 20) | m(z);
  }
  // The slot holding k, or the empty one where it would go (linear probing).
  std::size_t find(std::uint64_t k) const {
    const std::size_t mask = keys_.size() - 1;
    std::size_t slot = (k * 0x9E3779B97F4A7C15ull) >> 17 & mask;
    while (keys_[slot] != kEmpty && keys_[slot] != k) slot = (slot + 1) & mask;
    return slot;
  }
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> heads_;
  std::vector<Vec3> kept_;
  std::vector<std::uint32_t> next_;
};

// The circumcentre of a tetrahedron and its squared circumradius; false for a flat one.
bool circumsphere(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3& centre, double& radius2) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double det = 2 * dot(u, cross(v, w));
  if (!(std::abs(det) > 0)) return false;
  const Vec3 offset =
      (dot(u, u) * cross(v, w) + dot(v, v) * cross(w, u) + dot(w, w) * cross(u, v)) / det;
  centre = a + offset;
  radius2 = dot(offset, offset);
  return std::isfinite(radius2);
}

// The size wanted at p, in the tetrahedron with vertices v at the barycentric weights: the
// vertices' sizes interpolated, bounded by the field's (or the field's alone when sizes do not
// extend from the boundary).
double sizeAt(const RefinementSizes& sizes, Vec3 p, const std::uint32_t* v,
              const double* weights) {
  double interpolated = 0;
  for (int k = 0; k < 4; ++k) interpolated += weights[k] * sizes.atVertex[v[k]];
  if (!sizes.field) return interpolated;
  const double field = sizes.field(p);
  return sizes.extendFromBoundary ? std::min(interpolated, field) : field;
}

// A tetrahedron on a kept face (the boundary, mostly) is poor when its fourth vertex stands
// badly over the face, which moving that vertex often cannot fix (it is a boundary node, or
// held by its other tetrahedra). The point where a regular tetrahedron on the face would have
// its apex is inserted instead, if no vertex is nearer than half the face's mean edge.
std::size_t standOnPoorBoundaryFaces(DelaunayTets& mesh, RefinementSizes& sizes) {
  constexpr double kPoor = 0.3;  // gamma
  std::vector<std::pair<std::uint32_t, int>> poor;
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t) {
    if (!mesh.alive(t)) continue;
    int kept = 0;
    while (kept < 4 && !mesh.constrained(t, kept)) ++kept;
    if (kept == 4) continue;
    const std::uint32_t* v = &mesh.vertices[4 * std::size_t{t}];
    if (tetGamma(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]) <
        kPoor)
      poor.push_back({t, kept});
  }
  std::size_t inserted = 0;
  for (const auto& [t, f] : poor) {
    if (!mesh.alive(t)) continue;
    const std::uint32_t* v = &mesh.vertices[4 * std::size_t{t}];
    const int* face = DelaunayTets::kFace[f];
    const Vec3 a = mesh.points[v[face[0]]], b = mesh.points[v[face[1]]],
               c = mesh.points[v[face[2]]];
    const double edge = (norm(b - a) + norm(c - b) + norm(a - c)) / 3;
    const Vec3 normal = normalized(cross(b - a, c - a));  // towards the tetrahedron
    const Vec3 apex = (a + b + c) / 3 + std::sqrt(2.0 / 3.0) * edge * normal;
    double weights[4];
    const std::uint32_t where = mesh.locate(apex, t, weights);
    if (where == kNoTet) continue;
    const double size = sizeAt(sizes, apex, &mesh.vertices[4 * std::size_t{where}], weights);
    if (mesh.insert(apex, where, 0.5 * edge) != DelaunayTets::Insertion::kInserted) continue;
    sizes.atVertex.push_back(size);
    ++inserted;
  }
  return inserted;
}

// The rounds of refineToSizes over one mesh.
class Refinement {
 public:
  Refinement(DelaunayTets& mesh, RefinementSizes& sizes) : mesh_(mesh), sizes_(sizes) {}

  RefinementStats run() {
    std::vector<std::uint32_t> active;
    for (std::uint32_t t = 0; t < mesh_.slotCount(); ++t)
      if (mesh_.alive(t)) active.push_back(t);
    for (int round = 0; round < kMaxRounds && !active.empty(); ++round) {
      collectCandidates(active, round);
      if (candidates_.empty()) break;
      ++stats_.rounds;
      spaceOut();
      active.clear();
      if (insertCandidates(active) == 0) break;
      if (sizes_.afterRound) sizes_.afterRound(mesh_.tetCount());
    }
    return stats_;
  }

 private:
  // The circumcentres of the tetrahedra of `active` (not yet examined this round) whose
  // circumradius exceeds kRadiusRatio times their vertices' mean size.
  void collectCandidates(const std::vector<std::uint32_t>& active, int round) {
    seen_.resize(mesh_.slotCount(), -1);
    candidates_.clear();
    for (std::uint32_t t : active) {
      if (!mesh_.alive(t) || seen_[t] == round) continue;
      seen_[t] = round;
      const std::uint32_t* v = &mesh_.vertices[4 * std::size_t{t}];
      const Vec3 &a = mesh_.points[v[0]], &b = mesh_.points[v[1]], &c = mesh_.points[v[2]],
                 &d = mesh_.points[v[3]];
      double size = 0;
      for (int k = 0; k < 4; ++k) size += sizes_.atVertex[v[k]] / 4;
      Vec3 centre;
      double radius2;
      if (!circumsphere(a, b, c, d, centre, radius2)) continue;
      if (radius2 <= kRadiusRatio * kRadiusRatio * size * size) continue;
      // A nearly flat tetrahedron's centre is far away: its centroid is taken instead.
      const Vec3 centroid = (a + b + c + d) / 4;
      const double reach = std::max({norm(a - centroid), norm(b - centroid), norm(c - centroid),
                                     norm(d - centroid)});
      if (norm(centre - centroid) > 4 * reach) centre = centroid;
      candidates_.push_back({centre, t, size});
    }
  }

  // Spaced out among themselves in the order they were made (that of the tetrahedra, made by
  // insertions along a Hilbert curve).
  void spaceOut() {
    filter_.reset(candidates_.size());
    std::size_t kept = 0;
    for (const Candidate& c : candidates_)
      if (filter_.keep(c.point, c.size))
        candidates_[kept++] = c;
      else
        ++stats_.refusedTooClose;
    candidates_.resize(kept);
  }

  // Inserts the candidates along the Hilbert curve; the tetrahedra made go to `made`.
  std::size_t insertCandidates(std::vector<std::uint32_t>& made) {
    places_.clear();
    for (const Candidate& c : candidates_) places_.push_back(c.point);
    std::size_t inserted = 0;
    for (std::uint32_t i : spatialOrder(places_)) {
      const Candidate& c = candidates_[i];
      const bool generatorAlive = mesh_.alive(c.tet);
      double weights[4];
      Vec3 p = c.point;
      std::uint32_t where = mesh_.locate(p, generatorAlive ? c.tet : mesh_.lastTet(), weights);
      if (where == kNoTet) {
        // Outside the domain (or behind a kept face): the generator's centroid instead.
        if (!generatorAlive) {
          ++stats_.refusedOther;
          continue;
        }
        const std::uint32_t* v = &mesh_.vertices[4 * std::size_t{c.tet}];
        p = (mesh_.points[v[0]] + mesh_.points[v[1]] + mesh_.points[v[2]] + mesh_.points[v[3]]) /
            4;
        where = c.tet;
        std::fill(weights, weights + 4, 0.25);
      }
      const double size = sizeAt(sizes_, p, &mesh_.vertices[4 * std::size_t{where}], weights);
      const DelaunayTets::Insertion result = mesh_.insert(p, where, kSpacing * size);
      if (result == DelaunayTets::Insertion::kInserted) {
        sizes_.atVertex.push_back(size);
        const auto created = mesh_.created();
        made.insert(made.end(), created.begin(), created.end());
        ++inserted;
      } else if (result == DelaunayTets::Insertion::kTooClose) {
        ++stats_.refusedTooClose;
      } else {
        ++stats_.refusedOther;
      }
    }
    stats_.inserted += inserted;
    return inserted;
  }

  DelaunayTets& mesh_;
  RefinementSizes& sizes_;
  RefinementStats stats_;
  std::vector<int> seen_;  // per slot, the last round that examined it
  std::vector<Candidate> candidates_;
  std::vector<Vec3> places_;
  CandidateFilter filter_;
};

}  // namespace

RefinementStats refineToSizes(DelaunayTets& mesh, RefinementSizes& sizes) {
  // A tetrahedron whose height is under 1e-3 of its longest edge is not made at all.
  mesh.refuseFlat(1e-3);
  // The field's sizes hold at the existing vertices too, where the boundary's may be smaller.
  if (sizes.field)
    for (std::size_t i = 0; i < sizes.atVertex.size(); ++i)
      sizes.atVertex[i] = std::min(sizes.atVertex[i], sizes.field(mesh.points[i]));
  RefinementStats stats = Refinement(mesh, sizes).run();
  stats.inserted += standOnPoorBoundaryFaces(mesh, sizes);
  return stats;
}

}  // namespace geomesh
