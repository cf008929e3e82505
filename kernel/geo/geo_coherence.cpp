// Coherence: merging coincident points, then the curves and surfaces that have become
// identical. The entity of the lowest tag survives, as in the built-in kernel of Gmsh, which
// leaves volumes alone (two volumes bounded by the same surfaces both stay).
#include <algorithm>
#include <cmath>
#include <cstdlib>

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

// Points sorted by x: each point looks for an earlier-tagged point within the tolerance among
// those whose x is close enough.
void GeoFactory::mergePoints() {
  const double tol = absoluteTolerance();
  std::multimap<double, int> kept;  // x -> tag of points that stay
  std::map<int, int> replacement;
  for (const auto& [tag, point] : points_) {
    int twin = 0;
    for (auto it = kept.lower_bound(point.xyz.x - tol);
         it != kept.end() && it->first <= point.xyz.x + tol && twin == 0; ++it)
      if (distance(points_.at(it->second).xyz, point.xyz) <= tol) twin = it->second;
    if (twin != 0)
      replacement[tag] = twin;
    else
      kept.emplace(point.xyz.x, tag);
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
      if (surface.extrusion)
        surface.extrusion->source = std::abs(replaced(surface.extrusion->source, replacement));
    }
    for (auto& [tag, volume] : volumes_) replaceIn(volume.embeddedCurves, replacement);
  } else if (dim == 2) {
    for (auto& [tag, loop] : surfaceLoops_) replaceIn(loop, replacement);
    for (auto& [tag, volume] : volumes_) {
      for (auto& shell : volume.shells) replaceIn(shell, replacement);
      replaceIn(volume.embeddedSurfaces, replacement);
      if (volume.extrusion)
        volume.extrusion->source = std::abs(replaced(volume.extrusion->source, replacement));
    }
  }
  if (dim == 0)
    for (auto& [tag, curve] : curves_)
      if (curve.extrusion)
        curve.extrusion->source = replaced(curve.extrusion->source, replacement);
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
