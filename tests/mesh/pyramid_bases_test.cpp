// Quadrangles on the boundary of a tetrahedral volume: a pyramid on each, apex inside the
// volume, the tetrahedra filling the rest, conforming and of the volume's measure.
#include <gtest/gtest.h>

#include <span>

#include "mesh/checks/mesh_check.h"
#include "mesh/pipeline/generate.h"
#include "mesh_measures.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::countOf;
using testing::cubeModel;
using testing::QuietSink;
using testing::totalVolume;

// Signed volume of a pyramid as two tetrahedra over its base's diagonal.
double pyramidVolume(const Mesh& mesh, std::span<const NodeIndex> n) {
  auto tet = [&](NodeIndex a, NodeIndex b, NodeIndex c, NodeIndex d) {
    const Vec3 o = mesh.node(a);
    return dot(cross(mesh.node(b) - o, mesh.node(c) - o), mesh.node(d) - o) / 6;
  };
  return tet(n[0], n[1], n[3], n[4]) + tet(n[1], n[2], n[3], n[4]);
}

double pyramidsVolume(const Mesh& mesh) {
  double volume = 0;
  const ElementBlock* block = mesh.find({3, 1})->findBlock(ElementType::Pyramid5);
  for (std::size_t e = 0; block && e < block->size(); ++e)
    volume += pyramidVolume(mesh, block->element(e));
  return volume;
}

TEST(PyramidBases, RecombinedFacesOfATetrahedralVolumeGetPyramids) {
  for (int faces : {1, 6}) {  // the bottom only, then every face
    Model model = cubeModel(0.25);  // surface 1 is its bottom, z = 0
    for (int s = 1; s <= faces; ++s) model.meshConstraints().recombinedSurfaces[s] = 45;
    Mesh mesh;
    QuietSink log;
    generateMesh(model, {}, 3, mesh, log);
    const std::size_t quads = countOf(mesh, 2, ElementType::Quad4);
    EXPECT_GT(quads, 4u * faces);
    EXPECT_EQ(countOf(mesh, 3, ElementType::Pyramid5), quads) << faces << " faces";
    const ElementBlock& pyramids = *mesh.find({3, 1})->findBlock(ElementType::Pyramid5);
    for (std::size_t e = 0; e < pyramids.size(); ++e) {
      const auto n = pyramids.element(e);
      EXPECT_GT(pyramidVolume(mesh, n), 0) << "pyramid " << e;
      const Vec3 apex = mesh.node(n[4]);  // inside the cube
      EXPECT_GT(apex.z, 0);
      EXPECT_LT(apex.z, 1);
      EXPECT_GT(apex.x, 0);
      EXPECT_LT(apex.x, 1);
    }
    EXPECT_NEAR(totalVolume(mesh) + pyramidsVolume(mesh), 1.0, 1e-9);
    const MeshCheckReport report = checkMesh(model, mesh);
    EXPECT_TRUE(report.ok()) << report.summary();
  }
}

}  // namespace
}  // namespace geomesh
