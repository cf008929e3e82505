// Every row of the 2D and 3D algorithm registries: available codes mesh a unit square or cube
// validly; the others fall back, with their warning.
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/msh_writer.h"
#include "geo_unit_square.h"
#include "kernel/geo/geo_factory.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/pipeline/generate.h"
#include "mesh/surfaces/surface_algorithms.h"
#include "mesh/volumes/volume_algorithms.h"

namespace geomesh {
namespace {

class RecordingSink final : public MessageSink {
 public:
  std::vector<std::string> warnings;
  void info(std::string_view) override {}
  void warning(std::string_view m) override { warnings.emplace_back(m); }
};

// The unit cube [0, 1]^3 (six plane surfaces, one volume) meshed at size h.
Model unitCube(double h) {
  GeoFactory geo;
  int tag = 1;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) geo.addPoint(tag++, {double(x), double(y), double(z)}, h);
  // Points: 1 (0,0,0) 2 (1,0,0) 3 (0,1,0) 4 (1,1,0), 5..8 the same at z = 1.
  const int edges[12][2] = {{1, 2}, {2, 4}, {4, 3}, {3, 1}, {5, 6}, {6, 8},
                            {8, 7}, {7, 5}, {1, 5}, {2, 6}, {4, 8}, {3, 7}};
  for (int e = 0; e < 12; ++e) geo.addLine(e + 1, edges[e][0], edges[e][1]);
  const std::vector<std::vector<int>> loops = {{1, 2, 3, 4},    {5, 6, 7, 8},
                                               {1, 10, -5, -9}, {2, 11, -6, -10},
                                               {3, 12, -7, -11}, {4, 9, -8, -12}};
  for (int s = 0; s < 6; ++s) {
    geo.addCurveLoop(s + 1, loops[s]);
    geo.addPlaneSurface(s + 1, {s + 1});
  }
  geo.addSurfaceLoop(1, {1, 2, 3, 4, 5, 6});
  geo.addVolume(1, {1});
  Model model;
  geo.synchronize(model);
  return model;
}

std::string mshText(const Model& model, const Mesh& mesh) {
  std::ostringstream out;
  writeMsh(out, model, mesh, {});
  return out.str();
}

TEST(SurfaceAlgorithms, RowsAreSortedAndNamesUnique) {
  std::set<std::string> names;
  int last = 0;
  for (const SurfaceAlgorithm& row : surfaceAlgorithms()) {
    EXPECT_GT(row.code, last);
    last = row.code;
    EXPECT_TRUE(names.insert(row.name).second) << row.name;
    if (row.alias) {
      EXPECT_TRUE(names.insert(row.alias).second) << row.alias;
    }
    EXPECT_EQ(findSurfaceAlgorithm(row.code), &row);
    EXPECT_EQ(findSurfaceAlgorithm(row.name), &row);
    ASSERT_NE(findSurfaceAlgorithm(row.fallback), nullptr);
    EXPECT_NE(findSurfaceAlgorithm(row.fallback)->mesh, nullptr);
  }
  EXPECT_EQ(findSurfaceAlgorithm("tri"), findSurfaceAlgorithm("del2d"));
  EXPECT_EQ(findSurfaceAlgorithm(4), nullptr);
  EXPECT_EQ(findSurfaceAlgorithm("nonsense"), nullptr);
}

TEST(SurfaceAlgorithms, EveryAvailableCodeMeshesTheUnitSquare) {
  const Model model = geoUnitSquare(0.1);
  for (const SurfaceAlgorithm& row : surfaceAlgorithms()) {
    if (!row.mesh) continue;
    SCOPED_TRACE(row.name);
    MeshOptions options;
    options.algorithm2D = row.code;
    Mesh mesh;
    RecordingSink log;
    generateMesh(model, options, 2, mesh, log);
    EXPECT_TRUE(log.warnings.empty());
    EXPECT_TRUE(whyUnavailable(row.code).empty());
    EXPECT_EQ(&surfaceAlgorithmFor(row.code), &row);
    EXPECT_TRUE(checkMesh(model, mesh).ok());
    // The anisotropic algorithm grows sizes from the boundary's, as the reference's BAMG does
    // (70 triangles here): fewer than the others.
    EXPECT_GT(mesh.elementCount(2), row.code == 3 ? 1u : row.code == 7 ? 60u : 100u);
  }
}

TEST(SurfaceAlgorithms, EveryUnavailableCodeFallsBackWithItsWarning) {
  const Model model = geoUnitSquare(0.1);
  for (const SurfaceAlgorithm& row : surfaceAlgorithms()) {
    if (row.mesh) continue;
    SCOPED_TRACE(row.name);
    const SurfaceAlgorithm& fallback = *findSurfaceAlgorithm(row.fallback);
    EXPECT_EQ(&surfaceAlgorithmFor(row.code), &fallback);
    MeshOptions options;
    options.algorithm2D = row.code;
    Mesh mesh;
    RecordingSink log;
    generateMesh(model, options, 2, mesh, log);
    ASSERT_EQ(log.warnings.size(), 1u);
    EXPECT_EQ(log.warnings[0], "Mesh.Algorithm " + std::to_string(row.code) + " (" + row.title +
                                   ") is not available: surfaces are meshed with " +
                                   fallback.title + " (" + std::to_string(fallback.code) + ")");
    Mesh expected;
    options.algorithm2D = fallback.code;
    generateMesh(model, options, 2, expected, log);
    EXPECT_EQ(mshText(model, mesh), mshText(model, expected));
  }
  EXPECT_EQ(whyUnavailable(4), "4 is not a 2D meshing algorithm");
  EXPECT_EQ(fallbackText(4), "Frontal-Delaunay (6)");
}

TEST(VolumeAlgorithms, RowsAreSortedAndNamesUnique) {
  std::set<std::string> names;
  int last = 0;
  for (const VolumeAlgorithm& row : volumeAlgorithms()) {
    EXPECT_GT(row.code, last);
    last = row.code;
    EXPECT_TRUE(names.insert(row.name).second) << row.name;
    if (row.alias) {
      EXPECT_TRUE(names.insert(row.alias).second) << row.alias;
    }
    EXPECT_FALSE(findSurfaceAlgorithm(row.name)) << row.name;
    EXPECT_EQ(findVolumeAlgorithm(row.code), &row);
    EXPECT_EQ(findVolumeAlgorithm(row.name), &row);
  }
  EXPECT_EQ(findVolumeAlgorithm("netgen"), findVolumeAlgorithm("front3d"));
  EXPECT_EQ(&volumeAlgorithmFor(42), findVolumeAlgorithm(1));
}

bool positiveTetrahedra(const Mesh& mesh) {
  const ElementBlock* tets = mesh.find({3, 1})->findBlock(ElementType::Tet4);
  if (!tets || tets->size() == 0) return false;
  for (std::size_t i = 0; i < tets->size(); ++i) {
    const auto t = tets->element(i);
    const Vec3 a = mesh.node(t[0]);
    if (dot(cross(mesh.node(t[1]) - a, mesh.node(t[2]) - a), mesh.node(t[3]) - a) <= 0)
      return false;
  }
  return true;
}

// The codes that are not available fall back to Delaunay, with a warning naming both.
TEST(VolumeAlgorithms, EveryCodeMeshesTheUnitCube) {
  const Model model = unitCube(0.25);
  Mesh reference;
  RecordingSink referenceLog;
  generateMesh(model, {}, 3, reference, referenceLog);
  for (const VolumeAlgorithm& row : volumeAlgorithms()) {
    SCOPED_TRACE(row.name);
    const VolumeAlgorithm& used = volumeAlgorithmFor(row.code);
    EXPECT_EQ(&used, row.mesh ? &row : findVolumeAlgorithm(row.fallback));
    ASSERT_NE(used.mesh, nullptr);
    MeshOptions options;
    options.algorithm3D = row.code;
    Mesh mesh;
    RecordingSink log;
    generateMesh(model, options, 3, mesh, log);
    if (row.mesh) {
      EXPECT_TRUE(log.warnings.empty());
    } else {
      ASSERT_EQ(log.warnings.size(), 1u);
      EXPECT_EQ(log.warnings[0], "Mesh.Algorithm3D " + std::to_string(row.code) + " (" +
                                     row.title + ") is not available: volumes are meshed " +
                                     "with Delaunay (1)");
    }
    EXPECT_TRUE(checkMesh(model, mesh).ok());
    EXPECT_TRUE(positiveTetrahedra(mesh));
    if (!row.mesh) {
      EXPECT_EQ(mshText(model, mesh), mshText(model, reference));
    }
  }
}

}  // namespace
}  // namespace geomesh
