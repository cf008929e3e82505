// ExtrusionMesher: structured meshes of entities extruded with Layers, cut by smallest node.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/structured/layer_normals.h"

namespace geomesh {

namespace post {
class ViewStore;
}

// Structured meshes of entities extruded with Layers{..} (and Recombine): a curve swept by a
// point gets one segment per layer element; a surface swept by a curve gets the source
// curve's nodes swept layer by layer (quadrangles, or each cut into two triangles); a volume
// swept by a surface gets prisms and hexahedra (Recombine) or tetrahedra, three per prism.
// The top of such a sweep is meshed as the image of its source. A boundary layer (a sweep along
// normals) moves the source nodes along the normals of LayerNormals instead of a motion. Node k of a sweep is the
// motion at the layer fraction k applied to the source node. A side curve of a layered sweep of a
// curve, joining an end of the source to the matching end of the top, is swept with the same
// layers even when the kernel does not record it.
//
// Quadrangles are cut, in surfaces and in prisms' faces alike, along the diagonal through
// their corner of smallest node index (Dompierre, Labbé, Vallet, Camarero, IMR 1999), so that
// neighbouring prisms and the lateral surfaces agree without looking at each other.
class ExtrusionMesher {
 public:
  // `views`: the session's, for boundary layers extruded Using View[v] (may be null).
  explicit ExtrusionMesher(const Model& model, const post::ViewStore* views = nullptr);

  // Whether the curve, surface or volume is itself extruded with layers (a sweep).
  bool sweeps(EntityId id) const;
  // The record of the extrusion with layers whose top the curve or surface is, or null.
  const ExtrusionRecord* imageRecord(EntityId id) const;

  // Meshes a swept curve or surface, whose boundary is meshed; each new node gets the target
  // size of the source node it comes from (Mesh::setNodeSize).
  void meshSwept(EntityId id, Mesh& mesh) const;
  // Meshes the top of an extrusion as the image of its source, which must be meshed: throws
  // MeshError naming the top when it is not.
  void meshImage(EntityId id, Mesh& mesh) const;

  // Whether the curve or surface belongs to a boundary layer grown from surfaces (or is bounded
  // by such a curve): it is meshed once the surfaces it grows from are, in the 2D stage.
  bool waitsForSurfaces(EntityId id) const;
  // Whether such a curve or surface can be meshed now: the surfaces its layers grow from have
  // their mesh in `mesh` and, for a surface, so have its boundary curves. (A layer grown from
  // the top of another layer waits for that layer.)
  bool layerReady(EntityId id, const Mesh& mesh) const;

  // Whether the curve, meshed by its own mesher, ends at a point a boundary layer moved: it is
  // meshed after the layer's curves, then follows its ends (followLayerEnds).
  bool touchesLayer(EntityId id) const;
  // Moves the interior nodes of such a curve by the moves of its ends, blended along it.
  void followLayerEnds(EntityId id, Mesh& mesh) const;

  // Where the boundary layers meshed by this mesher had to be made thinner than asked.
  std::vector<std::string> layerWarnings() const { return normals_->warnings(); }

  bool meshesVolume(int tag) const;
  // Run after the surfaces are meshed.
  void meshVolumes(Mesh& mesh) const;

 private:
  const ExtrusionRecord* sweepRecord(int curveTag) const;
  // The boundary-layer extrusions the curve or surface comes from: its sweep or its top's,
  // and for a curve those that moved its ends.
  std::vector<const ExtrusionRecord*> layerRecords(EntityId id) const;
  void implySideSweeps(const ModelSurface& surface);

  const Model& model_;
  double tolerance_ = 0;
  std::map<int, ExtrusionRecord> impliedSweeps_;       // side curve -> its sweep from a point
  std::map<int, const ExtrusionRecord*> topCurves_;    // top curve -> the surface's record
  std::map<int, const ExtrusionRecord*> topSurfaces_;  // top surface -> the volume's record
  std::unique_ptr<LayerNormals> normals_;
  std::map<int, const ExtrusionRecord*> layerPoints_;  // point a layer made -> its curve's record
};

// Whether the volume is extruded with layers.
bool isLayeredExtrusion(const ModelVolume& volume);

}  // namespace geomesh
