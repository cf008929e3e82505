// Coherence: merging coincident points, then the curves and surfaces that have become
// identical. The entity of the lowest tag survives, as in the built-in kernel of Gmsh, which
// leaves volumes alone (two volumes bounded by the same surfaces both stay).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <unordered_map>

#include "kernel/geo/geo_detail.h"
#include "kernel/geo/geo_factory.h"

namespace geomesh {

namespace {

int replaced(int signedTag, const std::map<int, int>& replacement) {
  auto it = replacement.find(std::abs(signedTag));
  if (it == replacement.end()) return signedTag;
  return signedTag < 0 ? -it->second : it->second;
}

void replaceIn(std::vector<int>& tags, const std::map<int, int>& replacement) {
  for (int& t : tags) t = replaced(t, replacement);
}

// A key that identifies a surface or volume by the set of its bounding entities.
std::vector<int> unsignedSet(const std::vector<std::vector<int>>& chains) {
  std::vector<int> key;
  for (const auto& chain : chains)
    for (int t : chain) key.push_back(std::abs(t));
  std::sort(key.begin(), key.end());
  return key;
}

}  // namespace

void GeoFactory::coherence() {
  mergePoints();
  mergeCurves();
  mergeSurfaces();
  resetHighWater();
}

namespace {

// Points hashed into cubes much wider than the tolerance: a point's twins lie in its own cube,
// or, for the few points within the tolerance of a face, in the cubes across.
struct Cell {
  long long i, j, k;
  friend bool operator==(const Cell&, const Cell&) = default;
};

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    const auto h = [](long long x) { return std::hash<long long>()(x); };
    return h(c.i) ^ (h(c.j) * 0x9e3779b97f4a7c15ULL) ^ (h(c.k) * 0xc2b2ae3d27d4eb4fULL);
  }
};

struct KeptPoint {
  int tag;
  Vec3 xyz;
};

class PointGrid {
 public:
  explicit PointGrid(double tolerance)
      : tolerance_(tolerance), size_(std::max(1024 * tolerance, 1e-300)) {}

  // The lowest tag of the kept points within the tolerance of p; 0 if none.
  int twinOf(Vec3 p) const {
    const Cell c = cellOf(p);
    int steps[3][2];  // per axis: neighbour offsets to visit (0 always; -1 or +1 near a face)
    const double x[3] = {p.x, p.y, p.z};
    const long long index[3] = {c.i, c.j, c.k};
    for (int axis = 0; axis < 3; ++axis) {
      const double low = static_cast<double>(index[axis]) * size_;
      steps[axis][0] = 0;
      const bool nearLow = x[axis] - low <= tolerance_;
      steps[axis][1] = nearLow ? -1 : (low + size_ - x[axis] <= tolerance_ ? 1 : 0);
    }
    int twin = 0;
    for (int a : {0, 1})
      for (int b : {0, 1})
        for (int d : {0, 1}) {
          if ((a && !steps[0][1]) || (b && !steps[1][1]) || (d && !steps[2][1])) continue;
          auto it = cells_.find({c.i + steps[0][a], c.j + steps[1][b], c.k + steps[2][d]});
          if (it == cells_.end()) continue;
          for (const KeptPoint& q : it->second)
            if (distance(q.xyz, p) <= tolerance_ && (twin == 0 || q.tag < twin)) twin = q.tag;
        }
    return twin;
  }

  void keep(int tag, Vec3 p) { cells_[cellOf(p)].push_back({tag, p}); }

 private:
  long long index(double x) const {
    return static_cast<long long>(std::clamp(std::floor(x / size_), -1e18, 1e18));
  }
  Cell cellOf(Vec3 p) const { return {index(p.x), index(p.y), index(p.z)}; }

  double tolerance_, size_;
  std::unordered_map<Cell, std::vector<KeptPoint>, CellHash> cells_;
};

}  // namespace

// In ascending tags, each point merges into the lowest earlier point within the tolerance.
void GeoFactory::coherePoints(const std::vector<int>& points) {
  for (int p : points) requireShape({0, p}, "Coherence");
  if (points.empty()) return;
  const int kept = std::abs(points.front());
  std::map<int, int> replacement;
  for (int p : points)
    if (std::abs(p) != kept) replacement[std::abs(p)] = kept;
  if (replacement.empty()) return;
  for (const auto& [from, to] : replacement) points_.erase(from);
  replaceTags(0, replacement);
  mergeCurves();
  mergeSurfaces();
  resetHighWater();
}

void GeoFactory::mergePoints() {
  PointGrid grid(absoluteTolerance());
  std::map<int, int> replacement;
  for (const auto& [tag, point] : points_) {
    if (layerPoints_.contains(tag)) continue;
    if (const int twin = grid.twinOf(point.xyz))
      replacement[tag] = twin;
    else
      grid.keep(tag, point.xyz);
  }
  for (const auto& [from, to] : replacement) points_.erase(from);
  if (!replacement.empty()) replaceTags(0, replacement);
  mergeLayerPoints(replacement);
}

// The points of boundary layers from the same source point and index are one point.
void GeoFactory::mergeLayerPoints(const std::map<int, int>& merged) {
  std::map<int, int> replacement;
  std::map<std::pair<int, int>, int> first;
  for (auto it = layerPoints_.begin(); it != layerPoints_.end();) {
    if (!points_.contains(it->first)) {
      it = layerPoints_.erase(it);
      continue;
    }
    if (const auto m = merged.find(it->second.first); m != merged.end())
      it->second.first = m->second;
    const auto [kept, added] = first.try_emplace(it->second, it->first);
    if (!added) {
      replacement[it->first] = kept->second;
      points_.erase(it->first);
      it = layerPoints_.erase(it);
      continue;
    }
    ++it;
  }
  if (!replacement.empty()) replaceTags(0, replacement);
}

// Curves of one kind through the same points (in either direction) are the same curve. They
// are first grouped by their unordered pair of ends, then compared point by point.
void GeoFactory::mergeCurves() {
  std::unordered_map<std::uint64_t, std::vector<const Curve*>> byEnds;
  std::map<int, int> replacement;
  for (const auto& [tag, curve] : curves_) {
    if (!curve.trace.empty()) continue;  // two discrete curves may join the same points
    const auto low = static_cast<std::uint32_t>(std::min(curve.start(), curve.end()));
    const auto high = static_cast<std::uint32_t>(std::max(curve.start(), curve.end()));
    auto& group = byEnds[(std::uint64_t{low} << 32) | high];
    int twin = 0;
    for (const Curve* other : group) {
      if (other->kind != curve.kind || other->points.size() != curve.points.size()) continue;
      if (other->points == curve.points) {
        twin = other->tag;
      } else if (std::equal(curve.points.rbegin(), curve.points.rend(), other->points.begin())) {
        twin = -other->tag;
      } else {
        continue;
      }
      break;
    }
    if (twin != 0)
      replacement[tag] = twin;
    else
      group.push_back(&curve);
  }
  if (replacement.empty()) return;
  for (const auto& [from, to] : replacement) curves_.erase(from);
  replaceTags(1, replacement);
}

void GeoFactory::mergeSurfaces() {
  std::map<std::vector<int>, int> seen;
  std::map<int, int> replacement;
  for (const auto& [tag, surface] : surfaces_) {
    if (surface.kind == SurfaceKind::Discrete) continue;  // no loops to compare
    auto [it, inserted] = seen.emplace(unsignedSet(surface.loops), tag);
    if (!inserted) replacement[tag] = it->second;
  }
  if (replacement.empty()) return;
  for (const auto& [from, to] : replacement) surfaces_.erase(from);
  replaceTags(2, replacement);
}

// Every reference to an entity of `dim` follows the replacement (signed: a negative target
// means the survivor runs the other way).
void GeoFactory::replaceTags(int dim, const std::map<int, int>& replacement) {
  for (auto& [id, group] : physicals_)
    if (id.dim == dim) {
      replaceIn(group.entities, replacement);
      for (int& e : group.entities) e = std::abs(e);
      std::sort(group.entities.begin(), group.entities.end());
      group.entities.erase(std::unique(group.entities.begin(), group.entities.end()),
                           group.entities.end());
    }
  lastMerges_[static_cast<std::size_t>(dim)].insert(replacement.begin(), replacement.end());
  if (dim == 0) {
    for (auto& [tag, curve] : curves_) replaceIn(curve.points, replacement);
    for (auto& [tag, curve] : curves_) replaceIn(curve.embeddedPoints, replacement);
    for (auto& [tag, surface] : surfaces_) replaceIn(surface.embeddedPoints, replacement);
    for (auto& [tag, volume] : volumes_) replaceIn(volume.embeddedPoints, replacement);
  } else if (dim == 1) {
    for (auto& [tag, loop] : curveLoops_) replaceIn(loop, replacement);
    for (auto& [tag, surface] : surfaces_) {
      for (auto& loop : surface.loops) replaceIn(loop, replacement);
      replaceIn(surface.embeddedCurves, replacement);
      if (surface.extrusion) {
        surface.extrusion->source = std::abs(replaced(surface.extrusion->source, replacement));
        surface.extrusion->top = std::abs(replaced(surface.extrusion->top, replacement));
      }
    }
    for (auto& [tag, volume] : volumes_) replaceIn(volume.embeddedCurves, replacement);
  } else if (dim == 2) {
    for (auto& [tag, loop] : surfaceLoops_) replaceIn(loop, replacement);
    for (auto& [tag, volume] : volumes_) {
      for (auto& shell : volume.shells) replaceIn(shell, replacement);
      replaceIn(volume.embeddedSurfaces, replacement);
      if (volume.extrusion) {
        volume.extrusion->source = std::abs(replaced(volume.extrusion->source, replacement));
        volume.extrusion->top = std::abs(replaced(volume.extrusion->top, replacement));
      }
    }
  }
  if (dim == 0)
    for (auto& [tag, curve] : curves_)
      if (curve.extrusion) {
        curve.extrusion->source = replaced(curve.extrusion->source, replacement);
        curve.extrusion->top = replaced(curve.extrusion->top, replacement);
      }
}

void GeoFactory::resetHighWater() {
  auto last = [](const auto& m) { return m.empty() ? 0 : m.rbegin()->first; };
  highWater_[0] = last(points_);
  highWater_[1] = last(curves_);
  highWater_[2] = last(surfaces_);
  highWater_[3] = last(volumes_);
  highWater_[kCurveLoop] = last(curveLoops_);
  highWater_[kSurfaceLoop] = last(surfaceLoops_);
}

}  // namespace geomesh
