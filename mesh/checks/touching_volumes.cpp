// touchingVolumes: triangles of different volumes' boundary surfaces found at the same place.
#include "mesh/checks/touching_volumes.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

namespace geomesh {

namespace {

using Corners = std::array<std::tuple<double, double, double>, 3>;

// A triangle of a surface's mesh, by the places of its corners (sorted).
struct Placed {
  Corners at;
  int surface;
};

}  // namespace

std::vector<std::string> touchingVolumes(const Model& model, const Mesh& mesh) {
  if (model.volumes().size() < 2) return {};
  // The volumes each surface bounds.
  std::map<int, std::set<int>> bounds;
  for (const auto& [tag, volume] : model.volumes())
    for (const auto& shell : volume.shells)
      for (int s : shell) bounds[std::abs(s)].insert(tag);
  std::vector<Placed> triangles;
  for (const auto& [surface, volumes] : bounds) {
    const EntityMesh* em = mesh.find({2, surface});
    const ElementBlock* block = em ? em->findBlock(ElementType::Triangle3) : nullptr;
    if (!block) continue;
    for (std::size_t i = 0; i < block->size(); ++i) {
      const auto t = block->element(i);
      Corners at;
      for (int k = 0; k < 3; ++k) {
        const Vec3 p = mesh.node(t[k]);
        at[k] = {p.x, p.y, p.z};
      }
      std::sort(at.begin(), at.end());
      triangles.push_back({at, surface});
    }
  }
  std::sort(triangles.begin(), triangles.end(), [](const Placed& a, const Placed& b) {
    return std::tie(a.at, a.surface) < std::tie(b.at, b.surface);
  });
  // Pairs of surfaces of different volumes with a triangle at the same place: how many, and
  // the first one's first corner.
  std::map<std::pair<int, int>, std::pair<int, Vec3>> met;
  for (std::size_t i = 0; i + 1 < triangles.size(); ++i) {
    const Placed &p = triangles[i], &q = triangles[i + 1];
    if (p.at != q.at || p.surface == q.surface) continue;
    if (bounds[p.surface] == bounds[q.surface]) continue;  // one volume folded on itself
    auto& entry = met[{p.surface, q.surface}];
    if (entry.first++ == 0)
      entry.second = {std::get<0>(p.at[0]), std::get<1>(p.at[0]), std::get<2>(p.at[0])};
  }
  std::vector<std::string> messages;
  for (const auto& [pair, seen] : met) {
    const int va = *bounds[pair.first].begin(), vb = *bounds[pair.second].begin();
    char where[96];
    std::snprintf(where, sizeof where, "(%.6g, %.6g, %.6g)", seen.second.x, seen.second.y,
                  seen.second.z);
    messages.push_back("volumes " + std::to_string(std::min(va, vb)) + " and " +
                       std::to_string(std::max(va, vb)) + " touch without sharing a surface: " +
                       "surfaces " + std::to_string(pair.first) + " and " +
                       std::to_string(pair.second) + " lie at the same place (" +
                       std::to_string(seen.first) + " triangles, one at " + where +
                       "), so the mesh is not connected there; Coherence or BooleanFragments "
                       "would make them one surface");
  }
  return messages;
}

}  // namespace geomesh
