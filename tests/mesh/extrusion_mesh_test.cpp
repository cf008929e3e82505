// Tests of layered extrusion meshes: quads, prisms, hexahedra, tets, and collapse on the axis.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "kernel/geo/geo_factory.h"
#include "mesh/pipeline/generate.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/core/quality.h"

namespace geomesh {
namespace {

constexpr double kPi = 3.14159265358979323846;

class SilentSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view text) override { warnings.emplace_back(text); }
  std::vector<std::string> warnings;
};

ExtrusionLayers layers(std::vector<int> elements, std::vector<double> heights, bool recombine) {
  return {std::move(elements), std::move(heights), recombine};
}

// The unit square [0, 1]^2 at z = 0 (surface 1), points of size h.
GeoFactory unitSquare(double h, double x0 = 0) {
  GeoFactory geo;
  geo.addPoint(1, {x0, 0, 0}, h);
  geo.addPoint(2, {x0 + 1, 0, 0}, h);
  geo.addPoint(3, {x0 + 1, 1, 0}, h);
  geo.addPoint(4, {x0, 1, 0}, h);
  for (int k = 1; k <= 4; ++k) geo.addLine(k, k, k % 4 + 1);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {1});
  return geo;
}

struct Meshed {
  Model model;
  Mesh mesh;
  SilentSink log;
};

void meshModel(Meshed& m, int dim) { generateMesh(m.model, MeshOptions{}, dim, m.mesh, m.log); }

std::size_t count(const Mesh& mesh, ElementType type, EntityId only = {-1, 0}) {
  std::size_t n = 0;
  for (const auto& [id, em] : mesh.entities())
    if (only.dim < 0 || id == only)
      if (const ElementBlock* b = em.findBlock(type)) n += b->size();
  return n;
}

double measure(const Mesh& mesh, int dim) {
  double total = 0;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks)
      if (dimension(b.type) == dim)
        for (std::size_t e = 0; e < b.size(); ++e)
          total += elementMeasure(mesh, b.type, b.element(e));
  return total;
}

using Face = std::array<NodeIndex, 4>;
Face faceKey(std::vector<NodeIndex> n) {
  while (n.size() < 4) n.push_back(~NodeIndex{0});
  std::sort(n.begin(), n.end());
  return {n[0], n[1], n[2], n[3]};
}

// Faces of the volume elements of the whole mesh, with the number of elements each bounds.
std::map<Face, int> volumeFaces(const Mesh& mesh) {
  std::map<Face, int> faces;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks)
      for (std::size_t e = 0; e < b.size(); ++e) {
        const auto n = b.element(e);
        if (b.type == ElementType::Tet4) {
          for (int i = 0; i < 4; ++i) ++faces[faceKey({n[i], n[(i + 1) % 4], n[(i + 2) % 4]})];
        } else if (b.type == ElementType::Prism6) {
          ++faces[faceKey({n[0], n[1], n[2]})];
          ++faces[faceKey({n[3], n[4], n[5]})];
          for (int i = 0; i < 3; ++i)
            ++faces[faceKey({n[i], n[(i + 1) % 3], n[(i + 1) % 3 + 3], n[i + 3]})];
        } else if (b.type == ElementType::Pyramid5) {
          ++faces[faceKey({n[0], n[1], n[2], n[3]})];
          for (int i = 0; i < 4; ++i) ++faces[faceKey({n[i], n[(i + 1) % 4], n[4]})];
        } else if (b.type == ElementType::Hex8) {
          ++faces[faceKey({n[0], n[1], n[2], n[3]})];
          ++faces[faceKey({n[4], n[5], n[6], n[7]})];
          for (int i = 0; i < 4; ++i)
            ++faces[faceKey({n[i], n[(i + 1) % 4], n[(i + 1) % 4 + 4], n[i + 4]})];
        }
      }
  return faces;
}

// Every face of a surface bounds as many volume elements as the surface bounds volumes, and
// every face bounding a single element is a surface's face.
void expectConformingVolumes(const Model& model, const Mesh& mesh) {
  std::map<Face, int> faces = volumeFaces(mesh);
  ASSERT_FALSE(faces.empty());
  std::map<Face, int> surfaceFaces;
  for (const auto& [id, em] : mesh.entities()) {
    if (id.dim != 2) continue;
    const int volumes = static_cast<int>(model.upward(id).size());
    for (const ElementBlock& b : em.blocks)
      for (std::size_t e = 0; e < b.size(); ++e) {
        const auto n = b.element(e);
        const Face f = faceKey({n.begin(), n.end()});
        surfaceFaces[f] = volumes;
        EXPECT_EQ(faces[f], volumes) << "a face of surface " << id.tag;
      }
  }
  for (const auto& [face, uses] : faces)
    if (uses == 1) EXPECT_TRUE(surfaceFaces.contains(face)) << "a face inside the volume is open";
    else EXPECT_EQ(uses, 2);
}

void expectCheckOk(const Model& model, const Mesh& mesh) {
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(ExtrusionMesh, CurveWithLayersAndRecombineGivesQuadrangles) {
  Meshed m;
  GeoFactory geo = unitSquare(0.1);
  geo.extrude({{1, 1}}, ExtrusionMotion::translate({0, 0, 1}), layers({5}, {1}, true));
  geo.synchronize(m.model);
  meshModel(m, 2);
  const std::size_t segments = count(m.mesh, ElementType::Line2, {1, 1});
  EXPECT_EQ(segments, 10u);
  const std::vector<int> surfaces = m.model.upward({1, 1});
  ASSERT_EQ(surfaces.size(), 2u);  // the square and the extruded wall
  const EntityId wall{2, surfaces[1]};
  EXPECT_EQ(count(m.mesh, ElementType::Quad4, wall), 5 * segments);
  EXPECT_EQ(count(m.mesh, ElementType::Triangle3, wall), 0u);
  EXPECT_NEAR(measure(m.mesh, 2), 2.0, 1e-9);
  expectCheckOk(m.model, m.mesh);
}

TEST(ExtrusionMesh, CurveWithLayersAloneGivesTwoTrianglesPerCell) {
  Meshed m;
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 0.1);
  geo.addPoint(2, {1, 0, 0}, 0.1);
  geo.addLine(1, 1, 2);
  geo.extrude({{1, 1}}, ExtrusionMotion::translate({0, 1, 0}), layers({5}, {1}, false));
  geo.synchronize(m.model);
  meshModel(m, 2);
  EXPECT_EQ(count(m.mesh, ElementType::Triangle3), 100u);
  EXPECT_EQ(count(m.mesh, ElementType::Quad4), 0u);
  EXPECT_EQ(count(m.mesh, ElementType::Line2), 30u);
  EXPECT_NEAR(measure(m.mesh, 2), 1.0, 1e-9);
  expectCheckOk(m.model, m.mesh);
}

TEST(ExtrusionMesh, GradedLayersPlaceNodesAtTheLayerFractions) {
  Meshed m;
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 0.1);
  geo.extrude({{0, 1}}, ExtrusionMotion::translate({0, 2, 0}), layers({2, 3}, {0.3, 1}, false));
  geo.synchronize(m.model);
  meshModel(m, 1);
  ASSERT_EQ(m.model.curves().size(), 1u);
  const auto& [tag, curve] = *m.model.curves().begin();
  const EntityMesh* em = m.mesh.find({1, tag});
  ASSERT_NE(em, nullptr);
  ASSERT_EQ(count(m.mesh, ElementType::Line2), 5u);
  const std::vector<double> expected = {0.3, 0.6, 0.6 + 1.4 / 3, 0.6 + 2.8 / 3};
  ASSERT_EQ(em->nodes.size(), expected.size());
  ASSERT_EQ(em->parametric.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_NEAR(m.mesh.node(em->nodes[k]).y, expected[k], 1e-12);
    EXPECT_NEAR(distance(curve.geometry->point(em->parametric[k]), m.mesh.node(em->nodes[k])), 0,
                1e-12);
  }
  expectCheckOk(m.model, m.mesh);
}

// Surface 1 of `geo` made transfinite (and recombined if asked), then swept up by 1.
Meshed sweptSquare(GeoFactory geo, ExtrusionLayers l, bool recombineSource) {
  Meshed m;
  geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), l);
  geo.synchronize(m.model);
  m.model.meshConstraints().transfiniteSurfaces[1] = TransfiniteSurface{};
  if (recombineSource) m.model.meshConstraints().recombinedSurfaces[1] = 45;
  meshModel(m, 3);
  return m;
}

TEST(ExtrusionMesh, SquareWithLayersAndRecombineGivesHexahedra) {
  const Meshed m = sweptSquare(unitSquare(0.25), layers({4}, {1}, true), true);
  const std::size_t quads = count(m.mesh, ElementType::Quad4, {2, 1});
  EXPECT_EQ(quads, 16u);
  EXPECT_EQ(count(m.mesh, ElementType::Hex8), 4 * quads);
  EXPECT_EQ(count(m.mesh, ElementType::Tet4), 0u);
  EXPECT_NEAR(measure(m.mesh, 3), 1.0, 1e-9);
  EXPECT_NEAR(measure(m.mesh, 2), 6.0, 1e-9);
  for (const std::string& w : m.log.warnings)
    EXPECT_EQ(w.find("not recombined"), std::string::npos) << w;
  expectCheckOk(m.model, m.mesh);
  expectConformingVolumes(m.model, m.mesh);
}

TEST(ExtrusionMesh, CheckFindsAnInvertedHexahedronAndAnOpenFace) {
  Meshed m = sweptSquare(unitSquare(0.25), layers({2}, {1}, true), true);
  EntityMesh& volume = m.mesh.entity({3, m.model.volumes().begin()->first});
  ElementBlock& hexes = volume.block(ElementType::Hex8);
  ASSERT_GT(hexes.size(), 0u);
  std::swap(hexes.nodes[1], hexes.nodes[3]);
  std::swap(hexes.nodes[5], hexes.nodes[7]);
  const MeshCheckReport inverted = checkMesh(m.model, m.mesh);
  ASSERT_FALSE(inverted.ok());
  EXPECT_NE(inverted.summary().find("non-positive Jacobian"), std::string::npos)
      << inverted.summary();
  hexes.nodes.resize(hexes.nodes.size() - 8);
  std::swap(hexes.nodes[1], hexes.nodes[3]);
  std::swap(hexes.nodes[5], hexes.nodes[7]);
  const MeshCheckReport open = checkMesh(m.model, m.mesh);
  ASSERT_FALSE(open.ok());
  EXPECT_EQ(open.summary().find("non-positive Jacobian"), std::string::npos) << open.summary();
}

TEST(ExtrusionMesh, TopSurfaceIsTheImageOfTheSource) {
  const Meshed m = sweptSquare(unitSquare(0.25), layers({4}, {1}, true), true);
  const ModelVolume& volume = m.model.volumes().begin()->second;
  ASSERT_TRUE(volume.extrusion);
  const EntityMesh* source = m.mesh.find({2, 1});
  const EntityMesh* top = m.mesh.find({2, volume.extrusion->top});
  ASSERT_NE(source, nullptr);
  ASSERT_NE(top, nullptr);
  const ElementBlock* a = source->findBlock(ElementType::Quad4);
  const ElementBlock* b = top->findBlock(ElementType::Quad4);
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->size(), b->size());
  for (std::size_t e = 0; e < a->size(); ++e) {
    Vec3 ca, cb;
    for (int k = 0; k < 4; ++k) {
      ca = ca + m.mesh.node(a->element(e)[k]) / 4.0;
      cb = cb + m.mesh.node(b->element(e)[k]) / 4.0;
    }
    EXPECT_NEAR(distance(ca + Vec3{0, 0, 1}, cb), 0, 1e-12) << "quadrangle " << e;
  }
}

TEST(ExtrusionMesh, SquareWithLayersOnlyGivesThreeTetrahedraPerPrism) {
  const Meshed m = sweptSquare(unitSquare(0.25), layers({4}, {1}, false), false);
  const std::size_t triangles = count(m.mesh, ElementType::Triangle3, {2, 1});
  EXPECT_EQ(triangles, 32u);
  EXPECT_EQ(count(m.mesh, ElementType::Tet4), 3 * 4 * triangles);
  EXPECT_EQ(count(m.mesh, ElementType::Quad4), 0u);
  EXPECT_NEAR(measure(m.mesh, 3), 1.0, 1e-9);
  expectCheckOk(m.model, m.mesh);
  expectConformingVolumes(m.model, m.mesh);
}

TEST(ExtrusionMesh, DiscSweptIntoACylinderGivesPrisms) {
  Meshed m;
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 0.2);
  geo.addPoint(2, {1, 0, 0}, 0.2);
  geo.addPoint(3, {0, 1, 0}, 0.2);
  geo.addPoint(4, {-1, 0, 0}, 0.2);
  geo.addPoint(5, {0, -1, 0}, 0.2);
  for (int k = 0; k < 4; ++k) geo.addCircleArc(k + 1, k + 2, 1, (k + 1) % 4 + 2);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {1});
  geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 2}), layers({3, 2}, {0.5, 1}, true));
  geo.synchronize(m.model);
  meshModel(m, 3);
  const std::size_t triangles = count(m.mesh, ElementType::Triangle3, {2, 1});
  EXPECT_GT(triangles, 0u);
  EXPECT_EQ(count(m.mesh, ElementType::Prism6), 5 * triangles);
  EXPECT_EQ(count(m.mesh, ElementType::Tet4), 0u);
  EXPECT_NEAR(measure(m.mesh, 3), 2 * [&] {
    double area = 0;
    const ElementBlock* b = m.mesh.find({2, 1})->findBlock(ElementType::Triangle3);
    for (std::size_t e = 0; e < b->size(); ++e)
      area += elementMeasure(m.mesh, ElementType::Triangle3, b->element(e));
    return area;
  }(), 1e-9);
  expectCheckOk(m.model, m.mesh);
  expectConformingVolumes(m.model, m.mesh);
}

TEST(ExtrusionMesh, QuarterTurnAwayFromTheAxisGivesHexahedra) {
  Meshed m;
  GeoFactory geo = unitSquare(0.2, 1);
  geo.extrude({{2, 1}}, ExtrusionMotion::rotate({0, 1, 0}, {0, 0, 0}, kPi / 2),
              layers({10}, {1}, true));
  geo.synchronize(m.model);
  m.model.meshConstraints().transfiniteSurfaces[1] = TransfiniteSurface{};
  m.model.meshConstraints().recombinedSurfaces[1] = 45;
  meshModel(m, 3);
  const std::size_t quads = count(m.mesh, ElementType::Quad4, {2, 1});
  EXPECT_EQ(quads, 25u);
  EXPECT_EQ(count(m.mesh, ElementType::Hex8), 10 * quads);
  // The square [1, 2] x [0, 1] turned by pi/2 about y: area times the centroid's path, less
  // the chords' shortfall (cos(pi/40) for 10 layers, to first order).
  const double exact = 1.5 * kPi / 2;
  EXPECT_NEAR(measure(m.mesh, 3), exact, 0.01 * exact);
  expectCheckOk(m.model, m.mesh);
  expectConformingVolumes(m.model, m.mesh);
}

TEST(ExtrusionMesh, LayeredTetrahedraMatchAnUnstructuredNeighbour) {
  Meshed m;
  GeoFactory geo = unitSquare(0.25);
  const std::vector<EntityId> first =
      geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 0.5}), layers({2}, {1}, false));
  geo.extrude({first[0]}, ExtrusionMotion::translate({0, 0, 1}), ExtrusionLayers{});
  geo.synchronize(m.model);
  meshModel(m, 3);
  ASSERT_EQ(m.model.volumes().size(), 2u);
  EXPECT_EQ(m.model.upward(first[0]).size(), 2u);
  EXPECT_NEAR(measure(m.mesh, 3), 1.5, 1e-9);
  expectCheckOk(m.model, m.mesh);
  expectConformingVolumes(m.model, m.mesh);
}

TEST(ExtrusionMesh, WithoutLayersTheMeshIsUnstructured) {
  Meshed m;
  GeoFactory geo = unitSquare(0.25);
  geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), ExtrusionLayers{});
  geo.synchronize(m.model);
  meshModel(m, 3);
  EXPECT_EQ(count(m.mesh, ElementType::Prism6), 0u);
  EXPECT_EQ(count(m.mesh, ElementType::Quad4), 0u);
  EXPECT_GT(count(m.mesh, ElementType::Tet4), 0u);
  EXPECT_NEAR(measure(m.mesh, 3), 1.0, 1e-9);
}

TEST(ExtrusionMesh, PrismsOnTheAxisCollapseIntoPyramidsAndTetrahedra) {
  Meshed m;
  GeoFactory geo = unitSquare(0.25);  // its side x = 0 lies on the axis
  geo.extrude({{2, 1}}, ExtrusionMotion::rotate({0, 1, 0}, {0, 0, 0}, kPi / 2),
              layers({6}, {1}, true));
  geo.synchronize(m.model);
  m.model.meshConstraints().transfiniteSurfaces[1] = TransfiniteSurface{};
  meshModel(m, 3);
  // 32 triangles: 4 with a side on the axis (tetrahedra), 4 with a corner (pyramids).
  EXPECT_EQ(count(m.mesh, ElementType::Tet4), 4u * 6);
  EXPECT_EQ(count(m.mesh, ElementType::Pyramid5), 4u * 6);
  EXPECT_EQ(count(m.mesh, ElementType::Prism6), 24u * 6);
  expectCheckOk(m.model, m.mesh);
  expectConformingVolumes(m.model, m.mesh);
}

TEST(ExtrusionMesh, HexahedraOnTheAxisCollapseIntoPrisms) {
  Meshed m;
  GeoFactory geo = unitSquare(0.25);
  geo.extrude({{2, 1}}, ExtrusionMotion::rotate({0, 1, 0}, {0, 0, 0}, kPi / 2),
              layers({6}, {1}, true));
  geo.synchronize(m.model);
  m.model.meshConstraints().transfiniteSurfaces[1] = TransfiniteSurface{};
  m.model.meshConstraints().recombinedSurfaces[1] = 45;
  meshModel(m, 3);
  EXPECT_EQ(count(m.mesh, ElementType::Prism6), 4u * 6);
  EXPECT_EQ(count(m.mesh, ElementType::Hex8), 12u * 6);
  expectCheckOk(m.model, m.mesh);
  expectConformingVolumes(m.model, m.mesh);
}

TEST(ExtrusionMesh, HexahedraTouchingTheAxisAtACornerAreAnErrorNamingTheVolume) {
  Meshed m;
  GeoFactory geo = unitSquare(0.25);  // only its corner (0, 0, 0) lies on the axis
  geo.extrude({{2, 1}}, ExtrusionMotion::rotate({1, -1, 1}, {0, 0, 0}, kPi / 2),
              layers({6}, {1}, true));
  geo.synchronize(m.model);
  m.model.meshConstraints().transfiniteSurfaces[1] = TransfiniteSurface{};
  m.model.meshConstraints().recombinedSurfaces[1] = 45;
  try {
    meshModel(m, 3);
    FAIL() << "no error";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity.dim, 3);
    EXPECT_NE(std::string(e.what()).find("rotation axis"), std::string::npos) << e.what();
  }
}

TEST(ExtrusionMesh, TetrahedraTouchingTheAxisStayValid) {
  Meshed m;
  GeoFactory geo = unitSquare(0.25);
  geo.extrude({{2, 1}}, ExtrusionMotion::rotate({0, 1, 0}, {0, 0, 0}, kPi / 2),
              layers({6}, {1}, false));
  geo.synchronize(m.model);
  meshModel(m, 3);
  EXPECT_GT(count(m.mesh, ElementType::Tet4), 0u);
  // A quarter of the cylinder of radius 1 and height 1, inscribed polygons aside.
  EXPECT_NEAR(measure(m.mesh, 3), kPi / 4, 0.02);
  expectCheckOk(m.model, m.mesh);
  expectConformingVolumes(m.model, m.mesh);
}

}  // namespace
}  // namespace geomesh
