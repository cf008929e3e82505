// DelaunayTets: walking point location and Bowyer-Watson cavities over flat arrays.
#include "mesh/volumes/delaunay_tets.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "mesh/core/predicates.h"
#include "mesh/core/spatial_sort.h"

namespace geomesh {

namespace {

// kEdgeApart[f][g]: the two corners of a tetrahedron other than f and g (f != g), the edge
// shared by its faces f and g. A table rather than a loop that fills a small array: reading
// that array back as a whole right after writing it stalls the store buffer.
constexpr int kEdgeApart[4][4][2] = {{{-1, -1}, {2, 3}, {1, 3}, {1, 2}},
                                     {{2, 3}, {-1, -1}, {0, 3}, {0, 2}},
                                     {{1, 3}, {0, 3}, {-1, -1}, {0, 1}},
                                     {{1, 2}, {0, 2}, {0, 1}, {-1, -1}}};

}  // namespace

std::uint32_t DelaunayTets::newSlot() {
  if (!free_.empty()) {
    const std::uint32_t t = free_.back();
    free_.pop_back();
    flags[t] = 0;
    return t;
  }
  const auto t = static_cast<std::uint32_t>(flags.size());
  vertices.resize(vertices.size() + 4);
  neighbours.resize(neighbours.size() + 4, kNoTet);
  flags.push_back(0);
  return t;
}

std::uint32_t DelaunayTets::locate(Vec3 p, std::uint32_t start, double barycentric[4]) const {
  std::uint32_t t = start;
  int from = -1;  // the face just crossed: p is on its inner side
  std::uint32_t turn = 0;
  const std::size_t limit = 4 * slotCount() + 16;
  for (std::size_t step = 0; step < limit; ++step) {
    const std::uint32_t* v = &vertices[4 * std::size_t{t}];
    int exit = -1;
    // Faces tried from a rotating first one, so that a degenerate walk cannot cycle forever.
    const int first = static_cast<int>(turn++ & 3u);
    for (int k = 0; k < 4; ++k) {
      const int f = (first + k) & 3;
      if (f == from) continue;
      const int* face = kFace[f];
      if (orient3d(points[v[face[0]]], points[v[face[1]]], points[v[face[2]]], p) < 0) {
        exit = f;
        break;
      }
    }
    if (exit < 0) {
      if (barycentric) {
        const Vec3 &a = points[v[0]], &b = points[v[1]], &c = points[v[2]], &d = points[v[3]];
        const double whole = dot(cross(b - a, c - a), d - a);
        barycentric[1] = dot(cross(p - a, c - a), d - a) / whole;
        barycentric[2] = dot(cross(b - a, p - a), d - a) / whole;
        barycentric[3] = dot(cross(b - a, c - a), p - a) / whole;
        barycentric[0] = 1 - barycentric[1] - barycentric[2] - barycentric[3];
        // Rounding may leave them slightly outside [0, 1] for a point on a face.
        for (int k = 0; k < 4; ++k) barycentric[k] = std::clamp(barycentric[k], 0.0, 1.0);
      }
      return t;
    }
    const std::uint32_t n = neighbours[4 * std::size_t{t} + exit];
    if (n == kNoTet || constrained(t, exit)) return kNoTet;
    t = n >> 2;
    from = static_cast<int>(n & 3u);
  }
  return kNoTet;
}

DelaunayTets::Insertion DelaunayTets::insert(Vec3 p, std::uint32_t start, double minDistance) {
  points.push_back(p);
  const Insertion result =
      insertVertex(static_cast<std::uint32_t>(points.size() - 1), start, minDistance);
  if (result != Insertion::kInserted) points.pop_back();
  return result;
}

bool DelaunayTets::removesKeptEdge(std::span<const std::uint32_t> cavity) const {
  // A kept edge of the cavity survives only if it is an edge of one of its boundary faces.
  for (std::uint32_t t : cavity) {
    const std::uint32_t* v = &vertices[4 * std::size_t{t}];
    for (int i = 0; i < 4; ++i) {
      if (!isKeptVertex(v[i])) continue;
      for (int j = i + 1; j < 4; ++j) {
        if (!isKeptVertex(v[j])) continue;
        const std::uint64_t key = vertexPairKey(v[i], v[j]);
        if (!std::binary_search(keptEdges_.begin(), keptEdges_.end(), key)) continue;
        bool onBoundary = false;
        for (std::uint32_t h : boundary_) {
          const std::uint32_t* w = &vertices[4 * std::size_t{h >> 2}];
          const int f = static_cast<int>(h & 3u);
          if (w[f] != v[i] && w[f] != v[j] &&
              std::count_if(w, w + 4, [&](std::uint32_t x) { return x == v[i] || x == v[j]; }) ==
                  2) {
            onBoundary = true;
            break;
          }
        }
        if (!onBoundary) return true;
      }
    }
  }
  return false;
}

bool DelaunayTets::shapeCavity(Vec3 p, std::uint32_t t0) {
  // Near kept faces the cavity may not be star-shaped from p: a tetrahedron with a boundary
  // face that does not see p strictly from inside leaves the cavity, until every boundary face
  // does. The cavity must keep the tetrahedron holding p and stay connected.
  // Seen from inside, and not nearly in the face's plane (see refuseFlat).
  auto seesFromInside = [&](std::uint32_t t, int f) {
    const std::uint32_t* v = &vertices[4 * std::size_t{t}];
    const int* face = kFace[f];
    const Vec3 &a = points[v[face[0]]], &b = points[v[face[1]]], &c = points[v[face[2]]];
    if (orient3d(a, b, c, p) <= 0) return false;
    if (minHeight_ <= 0) return true;
    const Vec3 normal = cross(b - a, c - a);
    const double longest = std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)});
    const double height = dot(normal, p - a);
    return height * height > minHeight_ * minHeight_ * longest * dot(normal, normal);
  };
  auto isBoundary = [&](std::uint32_t t, int f) {
    const std::uint32_t n = neighbours[4 * std::size_t{t} + f];
    return n == kNoTet || constrained(t, f) || !inCavity(n >> 2);
  };
  // Until a tetrahedron leaves, the faces that see p are collected as the boundary: most
  // cavities keep them all, and then need no second walk.
  bool shrunk = false, keptInside = false;
  boundary_.clear();
  for (bool changed = true; changed;) {
    changed = false;
    for (std::uint32_t t : cavity_) {
      if (!inCavity(t)) continue;
      for (int f = 0; f < 4; ++f) {
        if (!isBoundary(t, f)) continue;
        if (seesFromInside(t, f)) {
          if (shrunk) continue;
          boundary_.push_back(4 * t + static_cast<std::uint32_t>(f));
          // A kept face with the cavity on both sides cannot be re-made.
          const std::uint32_t n = neighbours[4 * std::size_t{t} + f];
          if (n != kNoTet && inCavity(n >> 2)) keptInside = true;
          continue;
        }
        if (t == t0) return false;
        flags[t] &= ~kInCavity;
        changed = shrunk = true;
        break;
      }
    }
  }
  if (!shrunk) return !keptInside;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < cavity_.size(); ++i) {
    const std::uint32_t t = cavity_[i];
    if (inCavity(t)) cavity_[kept++] = t;
  }
  cavity_.resize(kept);
  // Connected through faces that are not kept, from t0 (kReached while walked; boundary_
  // serves as the walk's queue).
  std::size_t reached = 1;
  boundary_.assign(1, t0);
  flags[t0] |= kReached;
  for (std::size_t i = 0; i < boundary_.size(); ++i)
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t t = boundary_[i];
      const std::uint32_t n = neighbours[4 * std::size_t{t} + f];
      if (n == kNoTet || constrained(t, f) || !inCavity(n >> 2) ||
          (flags[n >> 2] & kReached))
        continue;
      flags[n >> 2] |= kReached;
      boundary_.push_back(n >> 2);
      ++reached;
    }
  for (std::uint32_t t : cavity_) flags[t] &= ~kReached;
  if (reached != cavity_.size()) return false;
  // The cavity's boundary again, now that it is smaller.
  boundary_.clear();
  for (std::uint32_t t : cavity_)
    for (int f = 0; f < 4; ++f) {
      if (!isBoundary(t, f)) continue;
      // A kept face with the cavity on both sides cannot be re-made.
      const std::uint32_t n = neighbours[4 * std::size_t{t} + f];
      if (n != kNoTet && inCavity(n >> 2)) return false;
      boundary_.push_back(4 * t + static_cast<std::uint32_t>(f));
    }
  return true;
}

DelaunayTets::Insertion DelaunayTets::insertVertex(std::uint32_t vertex, std::uint32_t start,
                                                   double minDistance) {
  const Vec3 p = points[vertex];
  const std::uint32_t t0 = locate(p, start);
  if (t0 == kNoTet) return Insertion::kOutside;
  // Too close: a vertex of the cavity is the nearest one, so each tetrahedron is checked as
  // it joins, and most refusals come before the cavity is grown.
  const double limit = minDistance * minDistance;
  auto tooClose = [&](std::uint32_t t) {
    const std::uint32_t* v = &vertices[4 * std::size_t{t}];
    for (int k = 0; k < 4; ++k) {
      const Vec3 d = points[v[k]] - p;
      const double squared = dot(d, d);
      if (squared == 0 || squared < limit) return true;
    }
    return false;
  };
  if (tooClose(t0)) return Insertion::kTooClose;
  cavity_.clear();
  boundary_.clear();
  cavity_.push_back(t0);
  flags[t0] |= kInCavity;
  // A tetrahedron found outside the sphere test is marked (kReached) so that its other faces
  // on the cavity do not test it again; the marks go once the cavity is grown.
  outside_.clear();
  auto clearOutside = [&] {
    for (std::uint32_t t : outside_) flags[t] &= ~kReached;
  };
  auto refuse = [&](Insertion why) {
    for (std::uint32_t t : cavity_) flags[t] &= ~kInCavity;
    return why;
  };
  for (std::size_t i = 0; i < cavity_.size(); ++i) {
    const std::uint32_t t = cavity_[i];
    // The four neighbours' vertices are requested together, so that their cache misses
    // overlap instead of waiting on each sphere test in turn.
    for (int f = 0; f < 4; ++f)
      if (const std::uint32_t n = neighbours[4 * std::size_t{t} + f]; n != kNoTet)
        __builtin_prefetch(&vertices[4 * std::size_t{n >> 2}]);
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t n = neighbours[4 * std::size_t{t} + f];
      if (n == kNoTet || constrained(t, f)) continue;
      const std::uint32_t nt = n >> 2;
      if (flags[nt] & (kInCavity | kReached)) continue;
      const std::uint32_t* w = &vertices[4 * std::size_t{nt}];
      if (insphere(points[w[0]], points[w[1]], points[w[2]], points[w[3]], p) >= 0) {
        flags[nt] |= kInCavity;
        cavity_.push_back(nt);
        if (tooClose(nt)) {
          clearOutside();
          return refuse(Insertion::kTooClose);
        }
      } else {
        flags[nt] |= kReached;
        outside_.push_back(nt);
      }
    }
  }
  clearOutside();
  if (!shapeCavity(p, t0)) return refuse(Insertion::kDegenerate);
  if (!keptEdges_.empty() && removesKeptEdge(cavity_)) return refuse(Insertion::kKeptEdge);

  // The new tetrahedra: each boundary face joined to p (p replaces the vertex opposite it).
  struct NewTet {
    std::array<std::uint32_t, 4> v;
    std::uint32_t outer;
    int face;
    bool kept;
  };
  static thread_local std::vector<NewTet> made;
  made.clear();
  for (std::uint32_t h : boundary_) {
    const std::uint32_t t = h >> 2;
    const int f = static_cast<int>(h & 3u);
    NewTet n{{vertices[4 * std::size_t{t}], vertices[4 * std::size_t{t} + 1],
              vertices[4 * std::size_t{t} + 2], vertices[4 * std::size_t{t} + 3]},
             neighbours[h], f, constrained(t, f)};
    n.v[f] = vertex;
    made.push_back(n);
  }
  for (std::uint32_t t : cavity_) {
    flags[t] = kDeleted;
    free_.push_back(t);
  }
  const std::size_t tableSize = std::bit_ceil(4 * boundary_.size());
  hashKeys_.assign(tableSize, ~std::uint64_t{0});
  hashValues_.resize(tableSize);
  created_.clear();
  for (const NewTet& n : made) {
    const std::uint32_t t = newSlot();
    created_.push_back(t);
    for (int k = 0; k < 4; ++k) vertices[4 * std::size_t{t} + k] = n.v[k];
    neighbours[4 * std::size_t{t} + n.face] = n.outer;
    if (n.outer != kNoTet) neighbours[n.outer] = 4 * t + static_cast<std::uint32_t>(n.face);
    if (n.kept) flags[t] |= static_cast<std::uint8_t>(1u << n.face);
    // The other faces contain p and an edge of the boundary face: the new tetrahedron across
    // each is the other one on that edge.
    for (int g = 0; g < 4; ++g) {
      if (g == n.face) continue;
      const int* e = kEdgeApart[n.face][g];
      const std::uint64_t key = vertexPairKey(n.v[e[0]], n.v[e[1]]);
      std::size_t slot = (key * 0x9E3779B97F4A7C15ull) >> 20 & (tableSize - 1);
      while (hashKeys_[slot] != ~std::uint64_t{0} && hashKeys_[slot] != key)
        slot = (slot + 1) & (tableSize - 1);
      const std::uint32_t half = 4 * t + static_cast<std::uint32_t>(g);
      if (hashKeys_[slot] == key) {
        const std::uint32_t other = hashValues_[slot];
        neighbours[half] = other;
        neighbours[other] = half;
        hashKeys_[slot] = ~std::uint64_t{1};  // matched: a tombstone keeps probing right
      } else {
        hashKeys_[slot] = key;
        hashValues_[slot] = half;
      }
    }
  }
  last_ = created_.front();
  return Insertion::kInserted;
}

void DelaunayTets::keepEdges(std::span<const std::array<std::uint32_t, 2>> edges) {
  keptVertex_.assign(points.size(), 0);
  for (const auto& e : edges) {
    keptEdges_.push_back(vertexPairKey(e[0], e[1]));
    keptVertex_[e[0]] = keptVertex_[e[1]] = 1;
  }
  std::sort(keptEdges_.begin(), keptEdges_.end());
}

std::vector<std::uint32_t> DelaunayTets::liveTetrahedra() const {
  std::vector<std::uint32_t> tets;
  tets.reserve(4 * tetCount());
  for (std::uint32_t t = 0; t < slotCount(); ++t)
    if (alive(t))
      tets.insert(tets.end(), &vertices[4 * std::size_t{t}], &vertices[4 * std::size_t{t} + 4]);
  return tets;
}

DelaunayTets DelaunayTets::fromTetrahedra(
    std::vector<Vec3> points, std::vector<std::uint32_t> tets,
    std::span<const std::array<std::uint32_t, 3>> keptFaces) {
  DelaunayTets mesh;
  mesh.points = std::move(points);
  const std::size_t count = tets.size() / 4;
  mesh.vertices = std::move(tets);
  mesh.neighbours.assign(4 * count, kNoTet);
  mesh.flags.assign(count, 0);
  using Key = std::array<std::uint32_t, 3>;
  auto sorted = [](Key k) {
    std::sort(k.begin(), k.end());
    return k;
  };
  std::vector<std::pair<Key, std::uint32_t>> faces;
  faces.reserve(4 * count);
  for (std::uint32_t t = 0; t < count; ++t)
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t* v = &mesh.vertices[4 * std::size_t{t}];
      faces.push_back({sorted({v[kFace[f][0]], v[kFace[f][1]], v[kFace[f][2]]}),
                       4 * t + static_cast<std::uint32_t>(f)});
    }
  std::sort(faces.begin(), faces.end());
  std::vector<Key> kept;
  for (const Key& k : keptFaces) kept.push_back(sorted(k));
  std::sort(kept.begin(), kept.end());
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].first == faces[i].first) ++j;
    const bool isKept = std::binary_search(kept.begin(), kept.end(), faces[i].first);
    if (j - i == 2) {
      mesh.neighbours[faces[i].second] = faces[i + 1].second;
      mesh.neighbours[faces[i + 1].second] = faces[i].second;
    }
    if (j - i != 2 || isKept)
      for (std::size_t k = i; k < j; ++k)
        mesh.flags[faces[k].second >> 2] |=
            static_cast<std::uint8_t>(1u << (faces[k].second & 3u));
    i = j;
  }
  return mesh;
}

DelaunayTets DelaunayTets::build(std::span<const Vec3> input) {
  DelaunayTets mesh;
  const std::size_t n = input.size();
  if (n == 0) return mesh;
  // The points are stored in insertion order while meshing, so that consecutive insertions
  // touch nearby memory, and renumbered back at the end.
  const std::vector<std::uint32_t> order = spatialOrder(input);
  mesh.points.reserve(n + 4);
  for (std::uint32_t i : order) mesh.points.push_back(input[i]);
  Vec3 lo = input[0], hi = input[0];
  for (const Vec3& p : input) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const Vec3 center = (lo + hi) / 2;
  const double radius = std::max(norm(hi - lo), 1e-300);
  // A regular tetrahedron whose inscribed sphere (radius 20 R / sqrt 3) holds the points.
  const double k = 20 * radius;
  mesh.points.push_back(center + Vec3{k, k, k});
  mesh.points.push_back(center + Vec3{k, -k, -k});
  mesh.points.push_back(center + Vec3{-k, k, -k});
  mesh.points.push_back(center + Vec3{-k, -k, k});
  const auto c = static_cast<std::uint32_t>(n);
  const std::uint32_t t = mesh.newSlot();
  std::array<std::uint32_t, 4> corner{c, c + 1, c + 2, c + 3};
  if (orient3d(mesh.points[c], mesh.points[c + 1], mesh.points[c + 2], mesh.points[c + 3]) < 0)
    std::swap(corner[0], corner[1]);
  std::copy(corner.begin(), corner.end(), mesh.vertices.begin());
  mesh.last_ = t;
  for (std::uint32_t i = 0; i < n; ++i) mesh.insertVertex(i, mesh.last_);
  // Remove the enclosing corners and everything that uses them.
  for (std::uint32_t s = 0; s < mesh.slotCount(); ++s) {
    if (!mesh.alive(s)) continue;
    const std::uint32_t* v = &mesh.vertices[4 * std::size_t{s}];
    if (std::none_of(v, v + 4, [c](std::uint32_t x) { return x >= c; })) continue;
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t h = mesh.neighbours[4 * std::size_t{s} + f];
      if (h != kNoTet) mesh.neighbours[h] = kNoTet;
      mesh.neighbours[4 * std::size_t{s} + f] = kNoTet;
    }
    mesh.flags[s] = kDeleted;
    mesh.free_.push_back(s);
  }
  mesh.points.assign(input.begin(), input.end());
  for (std::uint32_t& v : mesh.vertices) v = v < n ? order[v] : v;
  for (std::uint32_t s = 0; s < mesh.slotCount(); ++s)
    if (mesh.alive(s)) {
      mesh.last_ = s;
      break;
    }
  return mesh;
}

}  // namespace geomesh
