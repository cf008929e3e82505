// Compound Curve{..} and Compound Surface{..}: several entities meshed as one, the elements then
// put back on the entities they lie on.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "kernel/messages.h"
#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_options.h"

namespace geomesh {

class DiscreteSurfaceGeometry;

// A curve of a compound curve: where it lies on the compound's parameter, [offset, offset +
// range length], run backwards when `reversed`.
struct CompoundCurvePart {
  int tag = 0;
  bool reversed = false;
  double offset = 0;
  Interval range;
};

// A surface of a compound surface; `flipped` when its triangles face the other way from the
// compound's (whose side is that of its first surface).
struct CompoundSurfacePart {
  int tag = 0;
  bool flipped = false;
};

// The model to mesh instead of the script's, and how to put its elements back.
//
// Each compound surface becomes one surface (tag numbered on from the model's) whose geometry
// is the discrete map of its surfaces' meshes, made first on their own at
// Mesh.CompoundMeshSizeFactor times the sizes; the curves inside it, and the points inside it
// that no other curve ends at, are left out. Each compound curve becomes one curve through its
// curves end to end; the points between them are left out. A compound that cannot be made (its
// entities do not form a chain or a patch that maps to the plane, or they are transfinite,
// periodic, extruded in layers or merged) is warned of and its entities are meshed one by one.
struct CompoundMeshing {
  struct Curve {
    int tag = 0;
    std::vector<CompoundCurvePart> parts;
  };
  struct Surface {
    int tag = 0;
    std::vector<CompoundSurfacePart> parts;
    std::shared_ptr<const DiscreteSurfaceGeometry> geometry;
    std::vector<int> partOfTriangle;  // per triangle of geometry->map(): index into parts
  };
  Model model;
  std::vector<Curve> curves;
  std::vector<Surface> surfaces;

  // Moves the elements and nodes of the compounds' entities in `mesh` (meshed from `model`)
  // onto the script's entities: a node or element of a compound curve to the curve its
  // parameter falls in, an element of a compound surface to the surface of the triangle
  // closest to its centroid (turned round to face that surface's way), a node to the surface
  // of the first element that uses it. `original` gives the parameters on those entities.
  void classify(const Model& original, Mesh& mesh) const;
};

// Meshes `parts` (a model of some of the script's surfaces, their curves and points) to 2D at
// the sizes the options ask for, times `factor`.
using PartMesher = std::function<void(const Model& parts, double factor, Mesh& mesh)>;

// nullopt when the model has no compound that can be made (the others are warned of on `log`).
std::optional<CompoundMeshing> planCompounds(const Model& model, const MeshOptions& options,
                                             int dim, const PartMesher& meshParts,
                                             MessageSink& log);

}  // namespace geomesh
