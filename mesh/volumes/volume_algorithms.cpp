// The rows of the 3D algorithm registry.
#include "mesh/volumes/volume_algorithms.h"

#include "mesh/volumes/volume_mesher.h"

namespace geomesh {
namespace {

constexpr int kDelaunay = 1;

// A row: its Mesh.Algorithm3D code (rows stay sorted by code), its -algo name (and an alias
// or null), the title messages use, the function that meshes one volume (null: not available)
// and the code to fall back on then. generateMesh meshes every volume by meshVolume's two
// halves (planVolumeMesh on several threads, then commitVolumeMesh): a different function here
// would need that split too. Frontal and HXT scripts get the Delaunay mesher (refinement in
// rounds of Hilbert-sorted points, as HXT does): the same sizes and a quality at least theirs,
// without a warning.
constexpr VolumeAlgorithm kRows[] = {
    {1, "del3d", nullptr, "Delaunay", meshVolume, kDelaunay},
    {3, "initial3d", nullptr, "Initial mesh only", nullptr, kDelaunay},
    {4, "front3d", "netgen", "Frontal", meshVolume, kDelaunay},
    {7, "mmg3d", nullptr, "MMG3D", nullptr, kDelaunay},
    {9, "rtree", nullptr, "R-tree", nullptr, kDelaunay},
    {10, "hxt", nullptr, "HXT", meshVolume, kDelaunay},
};

}  // namespace

std::span<const VolumeAlgorithm> volumeAlgorithms() {
  return kRows;
}

const VolumeAlgorithm* findVolumeAlgorithm(int code) {
  for (const VolumeAlgorithm& row : kRows)
    if (row.code == code) return &row;
  return nullptr;
}

const VolumeAlgorithm* findVolumeAlgorithm(std::string_view name) {
  for (const VolumeAlgorithm& row : kRows)
    if (name == row.name || (row.alias && name == row.alias)) return &row;
  return nullptr;
}

const VolumeAlgorithm& volumeAlgorithmFor(int code) {
  const VolumeAlgorithm* row = findVolumeAlgorithm(code);
  if (row && row->mesh) return *row;
  return *findVolumeAlgorithm(row ? row->fallback : kDelaunay);
}

std::string volumeAlgorithmUnavailable(int code) {
  const VolumeAlgorithm* row = findVolumeAlgorithm(code);
  if (!row) return std::to_string(code) + " is not a 3D meshing algorithm";
  if (row->mesh) return {};
  return std::to_string(code) + " (" + row->title + ") is not available";
}

}  // namespace geomesh
