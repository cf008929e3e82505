// The 3D meshing algorithms by Mesh.Algorithm3D code and -algo name: one row each.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_options.h"
#include "mesh/volumes/volume_mesher.h"

namespace geomesh {

// One Mesh.Algorithm3D value. `mesh` is null for the algorithms that are recognised but not
// available: volumes asking for them are meshed by the row of `fallback`.
struct VolumeAlgorithm {
  int code;           // Mesh.Algorithm3D value
  const char* name;   // -algo name
  const char* alias;  // another -algo name, or null
  const char* title;  // as messages name it
  void (*mesh)(const Model& model, const MeshOptions& options, int volumeTag,
               const InteriorSize& interiorSize, Mesh& mesh);
  int fallback;  // code used instead when `mesh` is null
};

// Every row, by increasing code.
std::span<const VolumeAlgorithm> volumeAlgorithms();
// The row of a code or of an -algo name (or alias); null if there is none.
const VolumeAlgorithm* findVolumeAlgorithm(int code);
const VolumeAlgorithm* findVolumeAlgorithm(std::string_view name);
// The row that meshes a volume asking for `code`: its own if available, else its fallback
// (Delaunay for the codes no row knows).
const VolumeAlgorithm& volumeAlgorithmFor(int code);
// Why `code` cannot mesh volumes itself ("10 (HXT) is not available"); empty when it can.
std::string volumeAlgorithmUnavailable(int code);

}  // namespace geomesh
