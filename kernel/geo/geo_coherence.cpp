// Coherence: merging coincident points, then the curves and surfaces that have become
// identical. The entity of the lowest tag survives, as in the built-in kernel of Gmsh, which
// leaves volumes alone (two volumes bounded by the same surfaces both stay).
#include <algorithm>
#include <cmath>
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

// Points hashed into cubes of the tolerance's size: a point's twins lie in its cube or in
// the 26 around it.
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

long long cellIndex(double x, double size) {
  return static_cast<long long>(std::clamp(std::floor(x / size), -1e18, 1e18));
}

Cell cellOf(Vec3 p, double size) {
  return {cellIndex(p.x, size), cellIndex(p.y, size), cellIndex(p.z, size)};
}

}  // namespace

// In ascending tags, each point merges into the first earlier point within the tolerance.
void GeoFactory::mergePoints() {
  const double tol = absoluteTolerance();
  const double cellSize = std::max(tol, 1e-300);  // cells at least as wide as the tolerance
  std::unordered_map<Cell, std::vector<int>, CellHash> kept;
  std::map<int, int> replacement;
  for (const auto& [tag, point] : points_) {
    const Cell c = cellOf(point.xyz, cellSize);
    int twin = 0;
    for (long long di = -1; di <= 1; ++di)
      for (long long dj = -1; dj <= 1; ++dj)
        for (long long dk = -1; dk <= 1; ++dk) {
          auto it = kept.find({c.i + di, c.j + dj, c.k + dk});
          if (it == kept.end()) continue;
          for (int other : it->second)
            if (distance(points_.at(other).xyz, point.xyz) <= tol && (twin == 0 || other < twin))
              twin = other;
        }
    if (twin != 0)
      replacement[tag] = twin;
    else
      kept[c].push_back(tag);
  }
  if (replacement.empty()) return;
  for (const auto& [from, to] : replacement) points_.erase(from);
  replaceTags(0, replacement);
}

void GeoFactory::mergeCurves() {
  std::map<std::pair<CurveKind, std::vector<int>>, int> seen;
  std::map<int, int> replacement;
  for (const auto& [tag, curve] : curves_) {
    std::vector<int> backwards(curve.points.rbegin(), curve.points.rend());
    if (auto it = seen.find({curve.kind, curve.points}); it != seen.end()) {
      replacement[tag] = it->second;
    } else if (auto back = seen.find({curve.kind, backwards}); back != seen.end()) {
      replacement[tag] = -back->second;
    } else {
      seen[{curve.kind, curve.points}] = tag;
    }
  }
  if (replacement.empty()) return;
  for (const auto& [from, to] : replacement) curves_.erase(from);
  replaceTags(1, replacement);
}

void GeoFactory::mergeSurfaces() {
  std::map<std::vector<int>, int> seen;
  std::map<int, int> replacement;
  for (const auto& [tag, surface] : surfaces_) {
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
