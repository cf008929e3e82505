// Compound Curve{..} and Compound Surface{..}: meshed as one entity, the elements then put
// back on the entities they lie on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "api/meshing.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/core/quality.h"
#include "mesh_measures.h"
#include "script_runner.h"

namespace geomesh::testing {
namespace {

std::size_t lines(const Mesh& mesh, int curve) {
  const EntityMesh* em = mesh.find({1, curve});
  const ElementBlock* b = em ? em->findBlock(ElementType::Line2) : nullptr;
  return b ? b->size() : 0;
}

double minGamma(const Mesh& mesh) {
  double worst = 1;
  for (const auto& [id, em] : mesh.entities())
    if (const ElementBlock* t = id.dim == 2 ? em.findBlock(ElementType::Triangle3) : nullptr)
      for (std::size_t e = 0; e < t->size(); ++e)
        worst = std::min(worst, triangleGamma(mesh.node(t->element(e)[0]),
                                              mesh.node(t->element(e)[1]),
                                              mesh.node(t->element(e)[2])));
  return worst;
}

// Whether a surface's mesh has a boundary layer part.
bool hasLayer(const Mesh& mesh) {
  for (const auto& [id, em] : mesh.entities())
    if (id.dim == 2 && em.layer && em.layer->triangles + em.layer->quadrangles > 0) return true;
  return false;
}

// A line from x = 0 to 1 split at x = 0.57, its second half drawn backwards.
constexpr const char* kSplitLine =
    "lc = 0.1;\nPoint(1) = {0, 0, 0, lc}; Point(2) = {0.57, 0, 0, lc}; Point(3) = {1, 0, 0, lc};\n"
    "Line(1) = {1, 2}; Line(2) = {3, 2};\n";

TEST(CompoundMeshing, CurvesAreMeshedAsOneLine) {
  ScriptRun apart, joined;
  apart.run(kSplitLine);
  api::generate(apart.session, 1);
  joined.run(std::string(kSplitLine) + "Compound Curve{1, 2};\n");
  api::generate(joined.session, 1);
  EXPECT_TRUE(joined.log.warnings.empty());
  // One by one: 6 + 5 segments; as one line of length 1 at size 0.1: 10, none ending at x = 0.57.
  EXPECT_EQ(lines(apart.session.mesh(), 1) + lines(apart.session.mesh(), 2), 11u);
  const Mesh& mesh = joined.session.mesh();
  EXPECT_EQ(lines(mesh, 1) + lines(mesh, 2), 10u);
  EXPECT_NEAR(measure(mesh, 1), 1, 1e-12);
  EXPECT_EQ(mesh.find({0, 2}), nullptr);
  for (int curve : {1, 2}) {
    const EntityMesh& em = *mesh.find({1, curve});
    const ElementBlock& b = *em.findBlock(ElementType::Line2);
    for (std::size_t e = 0; e < b.size(); ++e) {
      const Vec3 a = mesh.node(b.element(e)[0]), c = mesh.node(b.element(e)[1]);
      const double middle = (a.x + c.x) / 2;
      EXPECT_TRUE(curve == 1 ? middle < 0.57 : middle > 0.57) << "curve " << curve;
      // Each segment runs the way its curve does (curve 2 from x = 1 down to 0.57), one after
      // the other.
      EXPECT_TRUE(curve == 1 ? a.x < c.x : a.x > c.x);
      if (e > 0) {
        EXPECT_EQ(b.element(e)[0], b.element(e - 1)[1]);
      }
    }
    // The nodes carry their parameters on their own curve.
    const ModelCurve& c = *joined.session.model().curve(curve);
    ASSERT_EQ(em.parametric.size(), em.nodes.size());
    for (std::size_t k = 0; k < em.nodes.size(); ++k)
      EXPECT_LT(distance(c.geometry->point(em.parametric[k]), mesh.node(em.nodes[k])), 1e-12);
  }
  const MeshCheckReport report = checkMesh(joined.session.model(), mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

// A unit square cut into a wide part and a sliver 0.02 wide along x = 1; the sliver's loop
// runs clockwise, so that it faces down (-z) while the wide part faces up.
constexpr const char* kSquareWithSliver =
    "lc = 0.1;\n"
    "Point(1) = {0, 0, 0, lc}; Point(2) = {0.98, 0, 0, lc}; Point(3) = {1, 0, 0, lc};\n"
    "Point(4) = {1, 1, 0, lc}; Point(5) = {0.98, 1, 0, lc}; Point(6) = {0, 1, 0, lc};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};\n"
    "Line(5) = {5, 6}; Line(6) = {6, 1}; Line(7) = {2, 5};\n"
    "Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};\n"
    "Curve Loop(2) = {7, -4, -3, -2}; Plane Surface(2) = {2};\n";

TEST(CompoundMeshing, SurfacesAreMeshedAcrossTheCurveBetweenThem) {
  ScriptRun apart, joined;
  apart.run(kSquareWithSliver);
  api::generate(apart.session, 2);
  joined.run(std::string(kSquareWithSliver) +
             "Compound Curve{1, 2};\nCompound Curve{4, 5};\nCompound Surface{1, 2};\n");
  api::generate(joined.session, 2);
  EXPECT_TRUE(joined.log.warnings.empty()) << joined.log.warnings.front();
  const Mesh& mesh = joined.session.mesh();
  // One by one, the sliver's triangles are thin; meshed as one, the square's are not.
  EXPECT_LT(minGamma(apart.session.mesh()), 0.4);
  EXPECT_GT(minGamma(mesh), 0.6);
  EXPECT_NEAR(measure(mesh, 2), 1, 1e-9);
  // The sliver gets the few triangles whose centroids lie in it (perhaps none): 0.02 at most.
  EXPECT_LE(measure(mesh, 2, {2, 2}), 0.02);
  EXPECT_EQ(mesh.find({1, 7}), nullptr);  // the curve between them is not meshed
  // About a square's worth of triangles at size 0.1.
  const std::size_t triangles = count(mesh, ElementType::Triangle3);
  EXPECT_GT(triangles, 180u);
  EXPECT_LT(triangles, 320u);
  // Each triangle faces the way of the surface it was put on.
  for (int s : {1, 2}) {
    const EntityMesh* em = mesh.find({2, s});
    const ElementBlock* t = em ? em->findBlock(ElementType::Triangle3) : nullptr;
    for (std::size_t e = 0; t && e < t->size(); ++e) {
      const auto n = t->element(e);
      const Vec3 normal =
          cross(mesh.node(n[1]) - mesh.node(n[0]), mesh.node(n[2]) - mesh.node(n[0]));
      EXPECT_TRUE(s == 1 ? normal.z > 0 : normal.z < 0) << "surface " << s << " triangle " << e;
    }
  }
  const MeshCheckReport report = checkMesh(joined.session.model(), mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(CompoundMeshing, ACompoundThatIsNoChainIsMeshedOneByOne) {
  ScriptRun run;
  run.run(std::string(kSquareWithSliver) + "Compound Curve{1, 3};\n");
  api::generate(run.session, 1);
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_NE(run.log.warnings[0].find("Compound Curve{1, 3}: they do not form one chain; its "
                                     "curves are meshed one by one"),
            std::string::npos)
      << run.log.warnings[0];
  EXPECT_TRUE(checkMesh(run.session.model(), run.session.mesh()).ok());
}

TEST(CompoundMeshing, SurfacesFacingEitherWayKeepTheirSides) {
  ScriptRun run;
  // A unit square on top of the first, its loop clockwise (facing down), meshed with both.
  run.run(std::string(kSquareWithSliver) +
          "Point(7) = {1, 2, 0, lc}; Point(8) = {0, 2, 0, lc};\n"
          "Line(8) = {4, 7}; Line(9) = {7, 8}; Line(10) = {8, 6};\n"
          "Curve Loop(3) = {4, 5, -10, -9, -8}; Plane Surface(3) = {3};\n"
          "Compound Surface{2, 3, 1};\n");
  api::generate(run.session, 2);
  EXPECT_TRUE(run.log.warnings.empty());
  const Mesh& mesh = run.session.mesh();
  for (int inner : {4, 5, 7}) EXPECT_EQ(mesh.find({1, inner}), nullptr) << inner;
  EXPECT_NEAR(measure(mesh, 2), 2, 1e-9);
  EXPECT_NEAR(measure(mesh, 2, {2, 3}), 1, 0.05);
  // Each triangle faces as the surface it is on: surface 1 up, surface 3 down.
  auto facing = [&](int surface) {
    const ElementBlock& t = *mesh.find({2, surface})->findBlock(ElementType::Triangle3);
    int up = 0, down = 0;
    for (std::size_t e = 0; e < t.size(); ++e) {
      const auto n = t.element(e);
      const double z =
          cross(mesh.node(n[1]) - mesh.node(n[0]), mesh.node(n[2]) - mesh.node(n[0])).z;
      (z > 0 ? up : down) += 1;
    }
    return std::pair{up, down};
  };
  const auto [up1, down1] = facing(1);
  const auto [up3, down3] = facing(3);
  EXPECT_GT(up1, 0);
  EXPECT_EQ(down1, 0);
  EXPECT_EQ(up3, 0);
  EXPECT_GT(down3, 0);
  const MeshCheckReport report = checkMesh(run.session.model(), mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(CompoundMeshing, ACurveBetweenThemThatBoundsAnotherSurfaceKeepsThemApart) {
  ScriptRun run;
  // A wall standing on curve 7, between the two surfaces of the compound.
  run.run(std::string(kSquareWithSliver) +
          "Point(7) = {0.98, 0, 1, lc}; Point(8) = {0.98, 1, 1, lc};\n"
          "Line(8) = {2, 7}; Line(9) = {7, 8}; Line(10) = {8, 5};\n"
          "Curve Loop(3) = {8, 9, 10, -7}; Plane Surface(3) = {3};\nCompound Surface{1, 2};\n");
  api::generate(run.session, 2);
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_EQ(run.log.warnings[0], "Compound Surface{1, 2}: curve 7 between them also bounds "
                                 "surface 3; its surfaces are meshed one by one");
  ASSERT_NE(run.session.mesh().find({1, 7}), nullptr);
  EXPECT_TRUE(checkMesh(run.session.model(), run.session.mesh()).ok());
}

TEST(CompoundMeshing, EntitiesThatOthersNameByTagStayApart) {
  // A boundary layer along curve 1, a periodic copy of curve 2: neither compound is made, and
  // the layer is still built.
  ScriptRun layered;
  layered.run(std::string(kSplitLine) +
              "Point(4) = {1, 1, 0, lc}; Point(5) = {0, 1, 0, lc};\n"
              "Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 1};\n"
              "Curve Loop(1) = {1, -2, 3, 4, 5}; Plane Surface(1) = {1};\n"
              "Compound Curve{1, 2};\nField[1] = BoundaryLayer;\nField[1].CurvesList = {1};\n"
              "Field[1].Size = 0.01;\nField[1].Thickness = 0.03;\nBoundaryLayer Field = 1;\n");
  api::generate(layered.session, 2);
  ASSERT_EQ(layered.log.warnings.size(), 1u);
  EXPECT_EQ(layered.log.warnings[0], "Compound Curve{1, 2}: curve 1 is named by a BoundaryLayer "
                                     "field; its curves are meshed one by one");
  EXPECT_TRUE(hasLayer(layered.session.mesh()));
  ScriptRun periodic;
  periodic.run(std::string(kSplitLine) + "Point(4) = {1, 1, 0, lc}; Point(5) = {0.57, 1, 0, lc};\n"
               "Line(3) = {4, 5};\nPeriodic Curve{3} = {2} Translate{0, 1, 0};\n"
               "Compound Curve{1, 2};\n");
  api::generate(periodic.session, 1);
  ASSERT_EQ(periodic.log.warnings.size(), 1u);
  EXPECT_NE(periodic.log.warnings[0].find("curve 3 is a periodic copy of 2"), std::string::npos)
      << periodic.log.warnings[0];
}

TEST(CompoundMeshing, ABoxWithASplitFaceFillsItsVolume) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
          "Rectangle(10) = {0, 0, 1, 0.37, 1};\n"
          "BooleanFragments{ Volume{1}; Delete; }{ Surface{10}; Delete; }\n"
          "top() = Surface In BoundingBox{-0.1, -0.1, 0.9, 1.1, 1.1, 1.1};\n"
          "Compound Surface{top()};\nMesh.MeshSizeMax = 0.2;\n");
  api::generate(run.session, 3);
  EXPECT_TRUE(run.log.warnings.empty()) << run.log.warnings.front();
  const Mesh& mesh = run.session.mesh();
  EXPECT_NEAR(measure(mesh, 3), 1, 1e-9);
  EXPECT_NEAR(measure(mesh, 2), 6, 1e-9);
  const MeshCheckReport report = checkMesh(run.session.model(), mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(CompoundMeshing, ACurvedCompoundKeepsItsNodesOnItsSurfaces) {
  ScriptRun run;
  // Two quarters of a cylinder of radius 1 side by side, meshed as one.
  run.run("Point(1) = {1, 0, 0}; Point(2) = {0, 1, 0}; Point(3) = {-1, 0, 0};\n"
          "Point(4) = {0, 0, 0};\n"
          "Point(11) = {1, 0, 2}; Point(12) = {0, 1, 2}; Point(13) = {-1, 0, 2};\n"
          "Point(14) = {0, 0, 2};\nCircle(1) = {1, 4, 2}; Circle(2) = {2, 4, 3};\n"
          "Circle(3) = {11, 14, 12}; Circle(4) = {12, 14, 13};\n"
          "Line(5) = {1, 11}; Line(6) = {2, 12}; Line(7) = {3, 13};\n"
          "Curve Loop(1) = {1, 6, -3, -5}; Surface(1) = {1};\n"
          "Curve Loop(2) = {2, 7, -4, -6}; Surface(2) = {2};\n"
          "Compound Surface{1, 2};\nMesh.MeshSizeMax = 0.15;\n");
  api::generate(run.session, 2);
  const Mesh& mesh = run.session.mesh();
  EXPECT_TRUE(run.log.warnings.empty());
  EXPECT_EQ(mesh.find({1, 6}), nullptr);
  // The nodes lie on the cylinder (checked too by checkMesh, at 1e-9 of the model's size).
  for (int s : {1, 2})
    for (NodeIndex n : mesh.find({2, s})->nodes)
      EXPECT_NEAR(std::hypot(mesh.node(n).x, mesh.node(n).y), 1, 1e-9);
  EXPECT_NEAR(measure(mesh, 2), 2 * 3.14159265358979, 0.02);
  const MeshCheckReport report = checkMesh(run.session.model(), mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

}  // namespace
}  // namespace geomesh::testing
