// LayerNormals: the directions boundary layers grow along, from the meshes of their sources.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

namespace extrusion {
class NodeLocator;
}
namespace post {
class ViewStore;
class ViewProbe;
}  // namespace post

// The unit normals at the nodes of the sources of the boundary layers (extrusions along
// normals) of each index of Using Index: at a node, the mean of the unit normals of the faces
// around it in the source surfaces of that index, each weighed by its angle there. Where no
// surface of that index is extruded (a layer in the plane, from curves), the segments of the
// source curves give the normals, each its direction turned a quarter to the right in the
// xy-plane (tangent x z). Layers of one index share their normals, so that touching layers
// made by separate extrusions meet along one face. Each column is then shortened where the
// thickest layer of its index would cross itself (shrinkLayer).
class LayerNormals {
 public:
  // `views`: the session's, for layers extruded Using View[v] (may be null).
  LayerNormals(const Model& model, const post::ViewStore* views);
  ~LayerNormals();
  LayerNormals(const LayerNormals&) = delete;
  LayerNormals& operator=(const LayerNormals&) = delete;

  // Whether the layers of this index grow from surfaces: their curves wait for the 2D mesh.
  bool fromSurfaces(int index) const { return surfaces_.contains(index); }
  // Whether every source surface of the layers of `index` has its mesh in `mesh`.
  bool sourcesMeshed(const Mesh& mesh, int index) const;

  // p, a node of a source of the layers of `index`, moved `height` along its normal. The
  // normals of an index are computed from the mesh on first use: its sources must be meshed.
  // Throws MeshError naming `asking` when p is no source node or its normal is undefined.
  // With `view` >= 0 (Using View[view]), the view's value at p scales the height (a scalar
  // view) or its vector replaces the normal (a vector view).
  Vec3 moved(const Mesh& mesh, int index, int view, Vec3 p, double height,
             EntityId asking) const;

  // Where the layers computed so far had to be made thinner than asked (see shrinkLayer),
  // one line per index, in index order.
  std::vector<std::string> warnings() const;

 private:
  struct Field;
  const Field& field(const Mesh& mesh, int index, EntityId asking) const;
  Vec3 viewDirection(int view, Vec3 p, Vec3 normal, EntityId asking) const;

  double tolerance_ = 0;
  std::map<int, std::set<int>> surfaces_;  // index -> source surfaces
  std::map<int, std::set<int>> curves_;    // index -> source curves
  std::map<int, double> surfaceHeights_;  // source surface -> its thickest layer (signed)
  std::map<int, double> curveHeights_;    // source curve -> its thickest layer (signed)
  mutable std::map<int, std::unique_ptr<Field>> fields_;
  const post::ViewStore* views_ = nullptr;
  mutable std::map<int, std::unique_ptr<post::ViewProbe>> probes_;  // view index -> probe
};

}  // namespace geomesh
