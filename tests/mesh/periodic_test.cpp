// Periodic curves and surfaces: the slave's mesh is the image of its master's, node for node,
// and the links survive writing and reading MSH files.
#include "mesh/structured/periodic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "mesh/curves/curve_mesher.h"
#include "mesh/pipeline/generate.h"
#include "io/msh_reader.h"
#include "io/msh_writer.h"
#include "mesh/checks/mesh_check.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::FlatGeometry;
using testing::SegmentGeometry;

std::vector<double> translation(double x, double y, double z) {
  return {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z, 0, 0, 0, 1};
}

std::vector<double> rotationZ(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

// Builds models in z = 0 tag by tag, so that tests choose which entity is the master.
struct ModelBuilder {
  Model model;
  void point(int tag, double x, double y, double size) { model.addPoint({tag, {x, y, 0}, size}); }
  void line(int tag, int a, int b, std::optional<Periodicity> periodic = std::nullopt) {
    ModelCurve c{tag, a, b,
                 std::make_shared<SegmentGeometry>(model.point(a)->xyz, model.point(b)->xyz)};
    c.periodic = std::move(periodic);
    model.addCurve(std::move(c));
  }
  // The square [x, x + 1] x [y, y + 1] with corner sizes `sizes`, tags from `first`: points and
  // curves first..first+3 (curve k from point k to k + 1), surface `first`.
  void square(int first, double x, double y, const double (&sizes)[4],
              std::optional<Periodicity> periodic = std::nullopt) {
    const double corners[4][2] = {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
    for (int k = 0; k < 4; ++k) point(first + k, corners[k][0], corners[k][1], sizes[k]);
    for (int k = 0; k < 4; ++k) line(first + k, first + k, first + (k + 1) % 4);
    ModelSurface s{first, {{first, first + 1, first + 2, first + 3}},
                   std::make_shared<FlatGeometry>(1.0), {}, {}};
    s.periodic = std::move(periodic);
    model.addSurface(std::move(s));
  }
};

Mesh generate(const Model& model, int dim) {
  Mesh mesh;
  SilentSink log;
  generateMesh(model, {}, dim, mesh, log);
  return mesh;
}

// Every pair of the entity's link: the node is the affine image of its master node.
void expectImages(const Mesh& mesh, EntityId slave, double scale) {
  const EntityMesh* em = mesh.find(slave);
  ASSERT_TRUE(em && em->periodic) << slave.dim << " " << slave.tag;
  ASSERT_FALSE(em->periodic->nodes.empty());
  for (const auto& [node, master] : em->periodic->nodes) {
    const Vec3 image = applyAffine(em->periodic->affine, mesh.node(master));
    EXPECT_LE(distance(image, mesh.node(node)), 1e-12 * scale) << node << " " << master;
  }
}

TEST(PeriodicCurve, SlaveIsTheImageOfItsGradedMaster) {
  // Curve 1 runs from (0,0) to (1,0), graded from 0.02 to 0.2; curve 3 runs from (1,1) to
  // (0,1) and is its translate by (0,1,0), so the image of the master's start is its end.
  ModelBuilder b;
  b.point(1, 0, 0, 0.02);
  b.point(2, 1, 0, 0.2);
  b.point(3, 1, 1, 0.5);
  b.point(4, 0, 1, 0.5);
  b.line(1, 1, 2);
  b.line(2, 2, 3);
  b.line(3, 3, 4, Periodicity{1, translation(0, 1, 0)});
  b.line(4, 4, 1);
  const Mesh mesh = generate(b.model, 1);
  const EntityMesh* master = mesh.find({1, 1});
  const EntityMesh* slave = mesh.find({1, 3});
  ASSERT_GT(master->nodes.size(), 10u);
  EXPECT_EQ(slave->nodes.size(), master->nodes.size());
  EXPECT_EQ(slave->elementCount(), master->elementCount());
  expectImages(mesh, {1, 3}, 1);
  EXPECT_EQ(slave->periodic->nodes.size(), master->nodes.size() + 2);
  // The fine end of the slave is at (0, 1), its end point.
  const std::vector<NodeIndex> chain = curveNodeChain(b.model, mesh, 3);
  EXPECT_LT(distance(mesh.node(chain[chain.size() - 2]), mesh.node(chain.back())), 0.03);
  // Parameters are those of the nodes on the slave's geometry.
  for (std::size_t k = 0; k < slave->nodes.size(); ++k)
    EXPECT_NEAR(mesh.node(slave->nodes[k]).x, 1 - slave->parametric[k], 1e-12);
  // The end points are linked too: (1,1) to (1,0), (0,1) to (0,0).
  ASSERT_TRUE(mesh.find({0, 3})->periodic);
  EXPECT_EQ(mesh.find({0, 3})->periodic->master, 2);
  EXPECT_EQ(mesh.find({0, 4})->periodic->master, 1);
  EXPECT_TRUE(checkMesh(b.model, mesh).ok()) << checkMesh(b.model, mesh).summary();
}

TEST(PeriodicCurve, EndPointsThatAreNotImagesAreAnError) {
  ModelBuilder b;
  b.point(1, 0, 0, 0.1);
  b.point(2, 1, 0, 0.1);
  b.point(3, 1, 1, 0.1);
  b.point(4, 0, 2, 0.1);
  b.line(1, 1, 2);
  b.line(2, 3, 4, Periodicity{1, translation(0, 1, 0)});
  try {
    generate(b.model, 1);
    FAIL() << "no error";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity.dim, 1);
    EXPECT_EQ(e.entity.tag, 2);
    EXPECT_NE(std::string(e.what()).find("curve 2"), std::string::npos);
  }
}

TEST(PeriodicCurve, MasterIsMeshedFirstWhateverTheTags) {
  ModelBuilder b;
  b.point(1, 0, 1, 0.1);
  b.point(2, 1, 1, 0.1);
  b.point(3, 0, 0, 0.01);
  b.point(4, 1, 0, 0.1);
  b.line(1, 1, 2, Periodicity{2, translation(0, 1, 0)});
  b.line(2, 3, 4);
  const Mesh mesh = generate(b.model, 1);
  EXPECT_EQ(mesh.find({1, 1})->elementCount(), mesh.find({1, 2})->elementCount());
  expectImages(mesh, {1, 1}, 1);
}

// Surface 5 is the image of surface 1 (graded towards its first corner) by `affine`.
void expectPeriodicSurface(const std::vector<double>& affine, double x, double y, int slaveFirst,
                           int masterFirst) {
  ModelBuilder b;
  const double graded[4] = {0.03, 0.2, 0.2, 0.2}, coarse[4] = {0.5, 0.5, 0.5, 0.5};
  // The slave's corners, in the order that makes its loop counterclockwise.
  b.square(masterFirst, 0, 0, graded);
  b.square(slaveFirst, x, y, coarse, Periodicity{masterFirst, affine});
  const Mesh mesh = generate(b.model, 2);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  const EntityMesh* master = mesh.find({2, masterFirst});
  const EntityMesh* slave = mesh.find({2, slaveFirst});
  ASSERT_GT(master->elementCount(), 50u);
  EXPECT_EQ(slave->elementCount(), master->elementCount());
  EXPECT_EQ(slave->nodes.size(), master->nodes.size());
  expectImages(mesh, {2, slaveFirst}, 1);
  // Each slave triangle is the image of a master triangle.
  std::map<NodeIndex, NodeIndex> masterOf;
  for (const auto& [node, from] : slave->periodic->nodes) masterOf[node] = from;
  std::set<std::array<NodeIndex, 3>> masterTriangles;
  const ElementBlock* mt = master->findBlock(ElementType::Triangle3);
  for (std::size_t e = 0; e < mt->size(); ++e) {
    std::array<NodeIndex, 3> t{mt->element(e)[0], mt->element(e)[1], mt->element(e)[2]};
    std::sort(t.begin(), t.end());
    masterTriangles.insert(t);
  }
  const ElementBlock* st = slave->findBlock(ElementType::Triangle3);
  for (std::size_t e = 0; e < st->size(); ++e) {
    std::array<NodeIndex, 3> t{};
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(masterOf.contains(st->element(e)[k]));
      t[k] = masterOf[st->element(e)[k]];
    }
    std::sort(t.begin(), t.end());
    EXPECT_TRUE(masterTriangles.contains(t)) << e;
  }
  // The boundary curves were matched: each slave curve is linked.
  for (int k = 0; k < 4; ++k) expectImages(mesh, {1, slaveFirst + k}, 1);
}

TEST(PeriodicSurface, TranslatedSquare) {
  expectPeriodicSurface(translation(3, 0, 0), 3, 0, 5, 1);
}

TEST(PeriodicSurface, RotatedSquareWithTheSlaveFirst) {
  // A quarter turn and a shift take [0,1]^2 to [-3,-2] x [0,1].
  std::vector<double> affine = rotationZ(std::acos(-1.0) / 2);
  affine[3] = -2;
  expectPeriodicSurface(affine, -3, 0, 1, 5);
}

TEST(PeriodicSurface, MirrorImageIsReorientedAlongTheSlaveNormal) {
  // x -> -1 - x reverses orientation; checkMesh verifies every triangle is positive.
  const std::vector<double> mirror{-1, 0, 0, -1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  expectPeriodicSurface(mirror, -2, 0, 5, 1);
}

TEST(PeriodicSurface, BoundaryThatIsNotAnImageIsAnError) {
  ModelBuilder b;
  const double sizes[4] = {0.2, 0.2, 0.2, 0.2};
  b.square(1, 0, 0, sizes);
  b.square(5, 3, 0, sizes, Periodicity{1, translation(2, 0, 0)});
  try {
    generate(b.model, 2);
    FAIL() << "no error";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity.dim, 2);
    EXPECT_EQ(e.entity.tag, 5);
  }
}

// Writes the mesh, reads it back and compares the links by node position.
void expectLinksSurvive(const Model& model, const Mesh& mesh, double version, bool binary) {
  std::stringstream file;
  writeMsh(file, model, mesh, {false, binary, version});
  EXPECT_NE(file.str().find("$Periodic"), std::string::npos);
  Model readModel;
  Mesh read;
  readMsh(file, readModel, read, "periodic.msh");
  std::size_t links = 0;
  for (const auto& [id, em] : mesh.entities()) {
    if (!em.periodic) continue;
    ++links;
    const EntityMesh* back = read.find(id);
    ASSERT_TRUE(back && back->periodic) << id.dim << " " << id.tag;
    EXPECT_EQ(back->periodic->master, em.periodic->master);
    EXPECT_EQ(back->periodic->affine, em.periodic->affine);
    ASSERT_EQ(back->periodic->nodes.size(), em.periodic->nodes.size());
    // Coordinates are written with 16 significant digits.
    for (std::size_t k = 0; k < em.periodic->nodes.size(); ++k) {
      EXPECT_LE(distance(read.node(back->periodic->nodes[k].first),
                         mesh.node(em.periodic->nodes[k].first)),
                1e-15);
      EXPECT_LE(distance(read.node(back->periodic->nodes[k].second),
                         mesh.node(em.periodic->nodes[k].second)),
                1e-15);
    }
  }
  EXPECT_EQ(links, 4u + 4u + 1u);  // points, curves, the surface
}

TEST(PeriodicIo, LinksAreWrittenAndReadBack) {
  ModelBuilder b;
  const double sizes[4] = {0.05, 0.2, 0.2, 0.2};
  b.square(1, 0, 0, sizes);
  b.square(5, 0, 2, sizes, Periodicity{1, translation(0, 2, 0)});
  const Mesh mesh = generate(b.model, 2);
  for (bool binary : {false, true}) {
    expectLinksSurvive(b.model, mesh, 4.1, binary);
    expectLinksSurvive(b.model, mesh, 2.2, binary);
  }
}

TEST(PeriodicIo, NoSectionWithoutPeriodicEntities) {
  ModelBuilder b;
  const double sizes[4] = {0.3, 0.3, 0.3, 0.3};
  b.square(1, 0, 0, sizes);
  const Mesh mesh = generate(b.model, 2);
  std::stringstream file;
  writeMsh(file, b.model, mesh, {});
  EXPECT_EQ(file.str().find("$Periodic"), std::string::npos);
}

TEST(PeriodicCheck, FindsANodeThatIsNotTheImageOfItsMaster) {
  Model model;
  Mesh mesh;
  mesh.reserveNodes(2);
  const NodeIndex a = mesh.addNode({0, 0, 0}), c = mesh.addNode({1, 0, 0});
  mesh.entity({0, 1}).nodes.push_back(a);
  mesh.entity({0, 2}).nodes.push_back(c);
  mesh.entity({0, 2}).periodic = PeriodicLink{1, translation(1, 0, 0), {{c, a}}};
  EXPECT_TRUE(checkMesh(model, mesh).ok()) << checkMesh(model, mesh).summary();
  mesh.entity({0, 2}).periodic = PeriodicLink{1, translation(0.5, 0, 0), {{c, a}}};
  const MeshCheckReport report = checkMesh(model, mesh);
  ASSERT_EQ(report.problems.size(), 1u);
  EXPECT_EQ(report.problems[0].entity.tag, 2);
}

}  // namespace
}  // namespace geomesh
