// The rows of the 2D algorithm registry and the functions they call.
#include "mesh/surfaces/surface_algorithms.h"

#include "mesh/surfaces/mesh_adapt.h"
#include "mesh/surfaces/smoothing.h"

namespace geomesh {
namespace {

// The domain's triangles, with all the points of the triangulation.
PlanarMesh domainMesh(SurfaceInterior& s) {
  PlanarMesh out{{s.tri.points().begin(), s.tri.points().end()},
                 {},
                 {s.tri.sizes().begin(), s.tri.sizes().end()}};
  for (std::uint32_t t = 0; t < s.tri.triangleCount(); ++t)
    if (s.inside[t])
      for (std::uint32_t i = 0; i < 3; ++i) out.triangles.push_back(s.tri.vertex(3 * t + i));
  return out;
}

PlanarMesh meshAdapt(SurfaceInterior& s) {
  return adaptMesh(s.tri, s.inside, s.firstMovable, s.smoothingPasses, s.metric,
                   s.fieldAndBound);
}

PlanarMesh initialMeshOnly(SurfaceInterior& s) {
  return domainMesh(s);
}

PlanarMesh delaunay(SurfaceInterior& s) {
  refineDelaunay(s.tri, s.inside, s.metric, s.field, s.bound);
  smoothTriangulation(s.tri, s.inside, s.firstMovable, s.smoothingPasses, s.metric);
  return domainMesh(s);
}

PlanarMesh frontalDelaunay(SurfaceInterior& s) {
  refineFrontal(s.tri, s.inside, s.metric, s.field, s.bound);
  smoothTriangulation(s.tri, s.inside, s.firstMovable, s.smoothingPasses, s.metric);
  return domainMesh(s);
}

// Plain smoothing would pull the square cells out of shape: it may not lower the worst
// quality.
PlanarMesh frontalDelaunayQuads(SurfaceInterior& s) {
  refineFrontalQuads(s.tri, s.inside, s.metric, s.field, s.bound);
  smoothTriangulation(s.tri, s.inside, s.firstMovable, s.smoothingPasses, s.metric,
                      SmoothingGuard::WorstQuality);
  return domainMesh(s);
}

// BAMG's slot: unit edges in the background's metric, graded from the boundary without one.
PlanarMesh anisotropic(SurfaceInterior& s) {
  return anisotropicMesh(s.tri, s.inside, s.firstMovable, s.smoothingPasses, s.metric,
                         s.anisotropic, s.bound, s.anisotropy);
}

// Delaunay on planes, MeshAdapt on the other surfaces.
PlanarMesh automatic(SurfaceInterior& s) {
  return s.metric ? meshAdapt(s) : delaunay(s);
}

constexpr int kFrontalDelaunay = 6;

// Adding a 2D algorithm: a file with its function `PlanarMesh f(SurfaceInterior&)` (which
// fills s.tri's domain and returns its triangles), then one row here: its Mesh.Algorithm
// code (rows stay sorted by code), its -algo name (and an alias or null), the title
// messages use, the function, and the code to fall back on if the function is null.
constexpr SurfaceAlgorithm kRows[] = {
    {1, "meshadapt", nullptr, "MeshAdapt", meshAdapt, kFrontalDelaunay},
    {2, "auto", nullptr, "Automatic", automatic, kFrontalDelaunay},
    {3, "initial2d", nullptr, "Initial mesh only", initialMeshOnly, kFrontalDelaunay},
    {5, "del2d", "tri", "Delaunay", delaunay, kFrontalDelaunay},
    {6, "front2d", "frontal", "Frontal-Delaunay", frontalDelaunay, kFrontalDelaunay},
    {7, "bamg", nullptr, "BAMG", anisotropic, kFrontalDelaunay},
    {8, "delquad", nullptr, "Frontal-Delaunay for Quads", frontalDelaunayQuads,
     kFrontalDelaunay},
    {9, "pack", nullptr, "Packing of Parallelograms", nullptr, kFrontalDelaunay},
    {11, "quadqs", nullptr, "Quasi-structured Quad", nullptr, kFrontalDelaunay},
};

}  // namespace

std::span<const SurfaceAlgorithm> surfaceAlgorithms() {
  return kRows;
}

const SurfaceAlgorithm* findSurfaceAlgorithm(int code) {
  for (const SurfaceAlgorithm& row : kRows)
    if (row.code == code) return &row;
  return nullptr;
}

const SurfaceAlgorithm* findSurfaceAlgorithm(std::string_view name) {
  for (const SurfaceAlgorithm& row : kRows)
    if (name == row.name || (row.alias && name == row.alias)) return &row;
  return nullptr;
}

const SurfaceAlgorithm& surfaceAlgorithmFor(int code) {
  const SurfaceAlgorithm* row = findSurfaceAlgorithm(code);
  if (row && row->mesh) return *row;
  return *findSurfaceAlgorithm(row ? row->fallback : kFrontalDelaunay);
}

std::string whyUnavailable(int code) {
  const SurfaceAlgorithm* row = findSurfaceAlgorithm(code);
  if (!row) return std::to_string(code) + " is not a 2D meshing algorithm";
  if (row->mesh) return {};
  return std::to_string(code) + " (" + row->title + ") is not available";
}

std::string fallbackText(int code) {
  const SurfaceAlgorithm& row = surfaceAlgorithmFor(code);
  return std::string(row.title) + " (" + std::to_string(row.code) + ")";
}

}  // namespace geomesh
