// meshingOrder: how each curve or surface is meshed, and in which order, copies after sources.
#pragma once

#include <map>
#include <vector>

#include "kernel/model.h"

namespace geomesh {

// How one curve or surface gets its mesh.
enum class MeshingMethod {
  Own,             // its own mesher (curve mesher, transfinite or unstructured surface)
  Swept,           // swept from a point or a curve with Layers (ExtrusionMesher)
  ExtrusionImage,  // the top of an extrusion with Layers: the image of its source's mesh
  PeriodicImage,   // a periodic slave: the image of its master's mesh
};

struct PlannedEntity {
  int tag = 0;
  MeshingMethod method = MeshingMethod::Own;
  int source = 0;  // for the images: the entity of the same dimension whose mesh is copied
};

// The entities of dimension `dim` (1 or 2) in the order they are meshed: an image comes after
// the entity it copies, whatever the order of their tags or definitions. A periodic slave is
// the image of its master even when it is also swept or an extrusion's top (both give the same
// nodes when the script is consistent, and the copy records the node pairs). `periodicCurves`
// holds the curves' periodicity (explicit and implied by Periodic Surface). Chains of
// extrusions that close on themselves (a full turn whose last top is merged with the first
// source) are broken at the entity of smallest tag, which is meshed by its own method. Throws
// MeshError naming a slave whose periodicity is circular.
std::vector<PlannedEntity> meshingOrder(const Model& model, int dim,
                                        const std::map<int, Periodicity>& periodicCurves);

}  // namespace geomesh
