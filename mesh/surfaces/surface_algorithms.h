// The 2D meshing algorithms by Mesh.Algorithm code and -algo name: one row each.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/surfaces/anisotropic_mesh.h"
#include "mesh/surfaces/delaunay2d.h"
#include "mesh/surfaces/frontal_refinement.h"
#include "mesh/surfaces/planar_mesh.h"
#include "mesh/surfaces/surface_metric.h"

namespace geomesh {

// What a 2D algorithm fills: the constrained Delaunay triangulation of a surface's boundary in its
// work plane, with the target size at each vertex (Triangulation2D::size, extended from the
// boundary), the triangles of the domain flagged in `inside`. Vertices from `firstMovable` on may
// move; the others are boundary and embedded nodes. `metric` is null on planes; `field` is the
// background size field (with curvature sizes), if any, and `bound` the sizes that keep
// elements from wrapping round tight bends, if any: see refineFrontal for how each is seen.
struct SurfaceInterior {
  Triangulation2D& tri;
  std::vector<std::uint8_t>& inside;
  std::uint32_t firstMovable;
  int smoothingPasses;
  const SurfaceMetric* metric;
  const WorkPlaneSize* field;
  const WorkPlaneSize* bound;
  const WorkPlaneSize* fieldAndBound;  // the smaller of the two; null if both are
  // For the anisotropic algorithm: the background's metric (field and curvature included,
  // restricted to the work plane), null without a background, and the options shaping it.
  const WorkPlaneMetric* anisotropic = nullptr;
  AnisotropicSettings anisotropy = {};
};

// One Mesh.Algorithm value. `mesh` is null for the algorithms that are recognised but not
// available: surfaces asking for them are meshed by the row of `fallback`, with a warning.
struct SurfaceAlgorithm {
  int code;           // Mesh.Algorithm / MeshAlgorithm Surface{..} value
  const char* name;   // -algo name
  const char* alias;  // another -algo name, or null
  const char* title;  // as messages name it
  PlanarMesh (*mesh)(SurfaceInterior&);
  int fallback;  // code used instead when `mesh` is null
};

// Every row, by increasing code.
std::span<const SurfaceAlgorithm> surfaceAlgorithms();
// The row of a code or of an -algo name (or alias); null if there is none.
const SurfaceAlgorithm* findSurfaceAlgorithm(int code);
const SurfaceAlgorithm* findSurfaceAlgorithm(std::string_view name);
// The row that meshes a surface asking for `code`: its own if available, else its fallback
// (Frontal-Delaunay for the codes no row knows).
const SurfaceAlgorithm& surfaceAlgorithmFor(int code);
// Why `code` is not meshed by its own row: "7 (BAMG) is not available" or "4 is not a 2D
// meshing algorithm"; empty if it is.
std::string whyUnavailable(int code);
// "Frontal-Delaunay (6)": the title and code of the row that meshes in place of `code`.
std::string fallbackText(int code);

}  // namespace geomesh
