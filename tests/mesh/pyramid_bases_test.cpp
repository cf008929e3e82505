// Quadrangles on the boundary of a tetrahedral volume: a pyramid on each, apex inside the
// volume, the tetrahedra filling the rest, conforming and of the volume's measure.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "kernel/geo/geo_factory.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/pipeline/generate.h"
#include "mesh_measures.h"

namespace geomesh {
namespace {

using testing::countOf;
using testing::QuietSink;
using testing::totalVolume;

// The unit cube of the built-in kernel, points of size h; surface 1 is its bottom (z = 0).
Model unitCube(double h) {
  GeoFactory geo;
  for (int k = 0; k < 8; ++k)
    geo.addPoint(k + 1, {double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)}, h);
  const int faces[6][4] = {{1, 2, 4, 3}, {5, 6, 8, 7}, {1, 2, 6, 5},
                           {3, 4, 8, 7}, {1, 3, 7, 5}, {2, 4, 8, 6}};
  std::map<std::pair<int, int>, int> lines;
  int nextLine = 1;
  for (int f = 0; f < 6; ++f) {
    std::vector<int> loop;
    for (int k = 0; k < 4; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 4];
      auto it = lines.find({std::min(a, b), std::max(a, b)});
      if (it == lines.end()) {
        geo.addLine(nextLine, std::min(a, b), std::max(a, b));
        it = lines.emplace(std::pair{std::min(a, b), std::max(a, b)}, nextLine++).first;
      }
      loop.push_back(a < b ? it->second : -it->second);
    }
    geo.addCurveLoop(f + 1, loop);
    geo.addPlaneSurface(f + 1, {f + 1});
  }
  geo.addSurfaceLoop(1, {1, 2, 3, 4, 5, 6});
  geo.addVolume(1, {1});
  Model model;
  geo.synchronize(model);
  return model;
}

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
    Model model = unitCube(0.25);
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
