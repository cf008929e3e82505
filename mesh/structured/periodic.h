// Periodic meshes: implied periodic curves, and slave curves and surfaces copied from masters.
#pragma once

#include <map>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Periodic meshes: a slave curve or surface (Periodic Curve/Surface{slave} = {master} + a
// transformation) is meshed as the image of its master's mesh, so that nodes match one to one
// across the transformation. Each slave's EntityMesh records the pairs in `periodic`.

// The image of p by a row-major 4x4 affine map.
Vec3 applyAffine(const std::vector<double>& affine, Vec3 p);

// The periodic curves of a model: those of Periodic Curve, and those a Periodic Surface
// implies: each curve bounding the master is matched with the curve bounding the slave that
// its image coincides with (an explicit Periodic Curve takes precedence). Throws MeshError
// naming the slave surface when a curve has no image among the slave's boundary curves.
std::map<int, Periodicity> periodicCurves(const Model& model);

// Meshes periodic slaves as images of their masters' meshes, one entity at a time: the caller
// meshes each master first (meshingOrder).
class PeriodicCopier {
 public:
  explicit PeriodicCopier(const Model& model);

  // Meshes the curve as the image of its master's mesh, each new node put on the slave's
  // geometry with its parameter and its master node's target size. Throws MeshError naming the
  // curve when its master has no mesh, when its end points are not the images of its master's,
  // or when its geometry is not the image of the master's.
  void copyCurve(int tag, const Periodicity& link, Mesh& mesh) const;
  // Links the end points of the curves of `links` to their masters' (the first curve, by tag,
  // decides for a point shared by several); run once every curve is meshed.
  void linkEndPoints(const std::map<int, Periodicity>& links, Mesh& mesh) const;
  // Meshes the periodic surface as the image of its master's mesh: the images of the master's
  // boundary nodes are the slave's curve nodes, the others are new nodes put on the slave's
  // geometry; elements are oriented along the slave's normal. Throws MeshError naming the
  // surface when its master has no mesh or its boundary nodes are not the images of the
  // master's.
  void copySurface(int tag, Mesh& mesh) const;

 private:
  const Model& model_;
  double scale_;
};

}  // namespace geomesh
