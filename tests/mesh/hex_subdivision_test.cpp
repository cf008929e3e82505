// Tests of Mesh.SubdivisionAlgorithm 2: every element of a 3D mesh split into hexahedra, the
// boundary into quadrangles, conforming, positively oriented, of the same volume.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "kernel/occ/occ_factory.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/core/quality.h"
#include "mesh/pipeline/generate.h"
#include "mesh/quads/subdivision.h"
#include "mesh_measures.h"
#include "mesh_test_models.h"
#include "tests/occ_fixtures.h"

namespace geomesh {
namespace {

using testing::countOf;
using testing::cubeModel;
using testing::QuietSink;

class WarningSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view text) override { warnings.emplace_back(text); }
  std::vector<std::string> warnings;
};

double volumeOf(const Mesh& mesh, ElementType type) {
  double volume = 0;
  for (const auto& [id, em] : mesh.entities())
    if (const ElementBlock* b = em.findBlock(type))
      for (std::size_t e = 0; e < b->size(); ++e)
        volume += elementMeasure(mesh, type, b->element(e));
  return volume;
}

// The Jacobian determinant of a hexahedron at each of its corners, along its three edges.
bool positiveAtEveryCorner(const Mesh& mesh, std::span<const NodeIndex> h) {
  static constexpr int kEdges[8][4] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                       {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};
  for (const auto& c : kEdges) {
    const Vec3 o = mesh.node(h[c[0]]);
    if (!(dot(cross(mesh.node(h[c[1]]) - o, mesh.node(h[c[2]]) - o), mesh.node(h[c[3]]) - o) > 0))
      return false;
  }
  return true;
}

MeshOptions hexahedra() {
  MeshOptions options;
  options.subdivisionAlgorithm = 2;
  return options;
}

// Tetrahedra into 4 hexahedra each, triangles into 3 quadrangles, segments into 2: nothing
// else is left, and the new nodes are the middles of edges, centres of faces and of cells.
TEST(HexSubdivision, CubeOfTetrahedraBecomesHexahedra) {
  const Model model = cubeModel(0.3);
  Mesh plain, split;
  QuietSink log;
  generateMesh(model, {}, 3, plain, log);
  generateMesh(model, hexahedra(), 3, split, log);
  const std::size_t tets = countOf(plain, 3, ElementType::Tet4);
  const std::size_t triangles = countOf(plain, 2, ElementType::Triangle3);
  ASSERT_GT(tets, 0u);
  EXPECT_EQ(countOf(split, 3, ElementType::Tet4), 0u);
  EXPECT_EQ(countOf(split, 2, ElementType::Triangle3), 0u);
  EXPECT_EQ(countOf(split, 3, ElementType::Hex8), 4 * tets);
  EXPECT_EQ(countOf(split, 2, ElementType::Quad4), 3 * triangles);
  EXPECT_EQ(split.elementCount(1), 2 * plain.elementCount(1));
  // Nodes: corners, edges, faces (each interior face with two tetrahedra, each boundary one
  // with one), cells.
  const std::size_t faces = (4 * tets + triangles) / 2;
  const std::size_t edges = plain.nodeCount() + faces - tets - 1;  // Euler: V - E + F - C = 1
  EXPECT_EQ(split.nodeCount(), plain.nodeCount() + edges + faces + tets);
  EXPECT_NEAR(volumeOf(split, ElementType::Hex8), 1.0, 1e-9);
  const ElementBlock& hexes = *split.find({3, 1})->findBlock(ElementType::Hex8);
  for (std::size_t e = 0; e < hexes.size(); ++e)
    EXPECT_TRUE(positiveAtEveryCorner(split, hexes.element(e))) << "hexahedron " << e;
  const MeshCheckReport report = checkMesh(model, split);
  EXPECT_TRUE(report.ok()) << report.summary();
}

// One prism into 6 hexahedra, one hexahedron into 8 (the reference: 21 and 27 nodes).
TEST(HexSubdivision, PrismAndHexahedronSplitByCorner) {
  struct Case {
    ElementType type;
    std::vector<Vec3> corners;
    std::size_t hexes, nodes;
    double volume;
  };
  const std::vector<Case> cases{
      {ElementType::Prism6,
       {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
       6,
       21,
       0.5},
      {ElementType::Hex8,
       {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {0, 1, 1}},
       8,
       27,
       2}};
  for (const Case& c : cases) {
    Model model;
    model.addVolume({1, {{}}});
    Mesh mesh;
    EntityMesh& em = mesh.entity({3, 1});
    for (Vec3 p : c.corners) em.nodes.push_back(mesh.addNode(p));
    em.block(c.type).nodes = em.nodes;
    EXPECT_EQ(subdivideIntoHexahedra(model, mesh), "");
    const ElementBlock* hexes = mesh.find({3, 1})->findBlock(ElementType::Hex8);
    ASSERT_NE(hexes, nullptr);
    EXPECT_EQ(hexes->size(), c.hexes);
    EXPECT_EQ(mesh.nodeCount(), c.nodes);
    EXPECT_EQ(mesh.find({3, 1})->nodes.size(), c.nodes);
    EXPECT_NEAR(volumeOf(mesh, ElementType::Hex8), c.volume, 1e-12);
    for (std::size_t e = 0; e < hexes->size(); ++e)
      EXPECT_TRUE(positiveAtEveryCorner(mesh, hexes->element(e))) << "hexahedron " << e;
  }
}

// Curved boundaries: the new nodes on the cylinder's and sphere's faces and circles lie on
// them (the final check measures it), every hexahedron is valid.
TEST(HexSubdivision, CurvedPartsStayValidAndOnTheirGeometry) {
  for (const occ_fixtures::Part& part : {occ_fixtures::cylinder(), occ_fixtures::sphere()}) {
    OccFactory occ;
    occ.importShapes(occ_fixtures::writeBrep(part));
    Model model;
    occ.synchronize(model);
    MeshOptions options = hexahedra();
    options.sizeMax = 0.4;
    Mesh mesh;
    QuietSink log;
    generateMesh(model, options, 3, mesh, log);
    EXPECT_EQ(countOf(mesh, 3, ElementType::Tet4), 0u) << part.name;
    EXPECT_GT(countOf(mesh, 3, ElementType::Hex8), 100u) << part.name;
    EXPECT_NEAR(volumeOf(mesh, ElementType::Hex8), part.volume, 0.03 * part.volume) << part.name;
    const MeshCheckReport report = checkMesh(model, mesh);
    EXPECT_TRUE(report.ok()) << part.name << ":\n" << report.summary();
  }
}

// Pyramids have no split into a few hexahedra (the reference uses 88 per pyramid): the mesh
// stays as it is, with a warning.
TEST(HexSubdivision, MeshWithPyramidsIsLeftAsItIs) {
  Model model = cubeModel(0.3);
  model.meshConstraints().recombinedSurfaces[1] = 45;
  Mesh mesh;
  WarningSink log;
  generateMesh(model, hexahedra(), 3, mesh, log);
  EXPECT_GT(countOf(mesh, 3, ElementType::Pyramid5), 0u);
  EXPECT_GT(countOf(mesh, 3, ElementType::Tet4), 0u);
  EXPECT_EQ(countOf(mesh, 3, ElementType::Hex8), 0u);
  ASSERT_EQ(log.warnings.size(), 1u);
  EXPECT_NE(log.warnings[0].find("pyramid"), std::string::npos);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

// Without a 3D mesh (-2), or on a model without volumes, nothing is split, as in the reference.
TEST(HexSubdivision, OnlyAfterMeshingVolumes) {
  const Model model = cubeModel(0.3);
  Mesh mesh;
  QuietSink log;
  generateMesh(model, hexahedra(), 2, mesh, log);
  EXPECT_EQ(countOf(mesh, 2, ElementType::Quad4), 0u);
  EXPECT_GT(countOf(mesh, 2, ElementType::Triangle3), 0u);
}

}  // namespace
}  // namespace geomesh
