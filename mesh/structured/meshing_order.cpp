// meshingOrder: each curve's or surface's method, sources before their images, cycles broken.
#include "mesh/structured/meshing_order.h"

#include <algorithm>
#include <set>
#include <string>

#include "mesh/core/mesh_error.h"
#include "mesh/structured/extrusion_mesher.h"

namespace geomesh {
namespace {

// What meshes the entity when nothing is copied to it: a sweep, else its own mesher.
MeshingMethod ownMethod(const ExtrusionMesher& extruded, EntityId id) {
  return extruded.sweeps(id) ? MeshingMethod::Swept : MeshingMethod::Own;
}

PlannedEntity plan(const ExtrusionMesher& extruded, EntityId id,
                   const std::optional<Periodicity>& periodic) {
  if (periodic) return {id.tag, MeshingMethod::PeriodicImage, periodic->master};
  if (const ExtrusionRecord* record = extruded.imageRecord(id))
    return {id.tag, MeshingMethod::ExtrusionImage, record->source};
  return {id.tag, ownMethod(extruded, id), 0};
}

bool isImage(const PlannedEntity& p) {
  return p.method == MeshingMethod::ExtrusionImage || p.method == MeshingMethod::PeriodicImage;
}

// The images left waiting only for each other: follows the sources from the smallest pending
// tag until one comes back, and turns the extrusion image of smallest tag on that cycle into an
// entity meshed by its own method.
void breakCycle(const ExtrusionMesher& extruded, int dim, std::map<int, PlannedEntity>& pending) {
  std::vector<int> path;
  std::set<int> seen;
  int tag = pending.begin()->first;
  while (seen.insert(tag).second) {
    path.push_back(tag);
    tag = pending.at(tag).source;
  }
  int chosen = 0;
  for (auto it = std::find(path.begin(), path.end(), tag); it != path.end(); ++it)
    if (pending.at(*it).method == MeshingMethod::ExtrusionImage && (chosen == 0 || *it < chosen))
      chosen = *it;
  if (chosen == 0) throw MeshError({dim, tag}, "its periodicity is circular");
  pending.at(chosen) = {chosen, ownMethod(extruded, {dim, chosen}), 0};
}

}  // namespace

std::vector<PlannedEntity> meshingOrder(const Model& model, int dim,
                                        const std::map<int, Periodicity>& periodicCurves) {
  const ExtrusionMesher extruded(model);
  std::map<int, PlannedEntity> all;
  if (dim == 1) {
    for (const auto& [tag, curve] : model.curves()) {
      const auto link = periodicCurves.find(tag);
      all[tag] = plan(extruded, {1, tag},
                      link == periodicCurves.end() ? std::nullopt
                                                   : std::optional<Periodicity>(link->second));
    }
  } else {
    for (const auto& [tag, surface] : model.surfaces())
      all[tag] = plan(extruded, {2, tag}, surface.periodic);
  }
  std::vector<PlannedEntity> order;
  std::map<int, PlannedEntity> pending;
  for (MeshingMethod first : {MeshingMethod::Own, MeshingMethod::Swept})
    for (const auto& [tag, p] : all)
      if (p.method == first) order.push_back(p);
  for (const auto& [tag, p] : all)
    if (isImage(p)) pending.emplace(tag, p);
  std::set<int> done;
  for (const PlannedEntity& p : order) done.insert(p.tag);
  while (!pending.empty()) {
    bool progress = false;
    for (auto it = pending.begin(); it != pending.end();) {
      const PlannedEntity& p = it->second;
      // A source that is no entity of the model: the copy reports it.
      if (isImage(p) && !done.contains(p.source) && all.contains(p.source)) {
        ++it;
        continue;
      }
      order.push_back(p);
      done.insert(p.tag);
      it = pending.erase(it);
      progress = true;
    }
    if (!progress) breakCycle(extruded, dim, pending);
  }
  return order;
}

}  // namespace geomesh
