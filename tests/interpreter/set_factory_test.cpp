// SetFactory: the OpenCASCADE factory builds boxes; what it cannot do yet goes to the built-in
// kernel with one warning per kind of statement.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/checks/mesh_check.h"
#include "script_runner.h"

namespace geomesh::testing {
namespace {

double tetrahedraVolume(const Mesh& mesh, int volumeTag) {
  const EntityMesh* part = mesh.find({3, volumeTag});
  if (!part) return 0;
  const ElementBlock* tets = part->findBlock(ElementType::Tet4);
  if (!tets) return 0;
  const auto xyz = mesh.coordinates();
  auto at = [&](NodeIndex n) { return Vec3{xyz[3 * n], xyz[3 * n + 1], xyz[3 * n + 2]}; };
  double total = 0;
  for (std::size_t i = 0; i < tets->size(); ++i) {
    const auto t = tets->element(i);
    const Vec3 a = at(t[0]);
    total += dot(cross(at(t[1]) - a, at(t[2]) - a), at(t[3]) - a) / 6;
  }
  return total;
}

TEST(SetFactory, OpenCascadeBoxIsAVolumeOfTheModel) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nBox(1) = {1, 0, 0, 1, 2, 3};\n");
  EXPECT_TRUE(run.log.warnings.empty()) << run.log.warnings.front();
  run.session.synchronize();
  const Model& model = run.session.model();
  EXPECT_EQ(model.volumes().size(), 1u);
  EXPECT_EQ(model.surfaces().size(), 6u);
  EXPECT_EQ(model.curves().size(), 12u);
  EXPECT_EQ(model.points().size(), 8u);
  const BoundingBox box = model.boundingBox();
  EXPECT_NEAR(box.min.x, 1, 1e-9);
  EXPECT_NEAR(box.min.y, 0, 1e-9);
  EXPECT_NEAR(box.min.z, 0, 1e-9);
  EXPECT_NEAR(box.max.x, 2, 1e-9);
  EXPECT_NEAR(box.max.y, 2, 1e-9);
  EXPECT_NEAR(box.max.z, 3, 1e-9);
}

TEST(SetFactory, BoxTagsAndQueries) {
  EXPECT_EQ(printed("SetFactory(\"OpenCASCADE\");\nBox(3) = {0, 0, 0, 1, 1, 1};\n"
                    "Box(-1) = {2, 0, 0, -1, 1, 1};\n"
                    "Printf(\"%g %g %g %g\", newv, newp, newl, news);\n"
                    "v() = Volume{:};\nPrintf(\"%g\", #v());\n"
                    "Printf(\"%g %g %g %g %g %g\", BoundingBox Volume{4});\n"
                    "Geometry.OldNewReg = 0;\nPrintf(\"%g %g\", newv, news);"),
            "25 17 25 25\n2\n1 -1e-07 -1e-07 2 1 1\n5 13\n");  // the reference's box
}

TEST(SetFactory, OpenCascadeBoxMeshesToItsVolume) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 2, 3};\nMesh.MeshSizeMax = 0.5;\n");
  run.session.generate(3);
  const MeshCheckReport report = checkMesh(run.session.model(), run.session.mesh());
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_NEAR(tetrahedraVolume(run.session.mesh(), 1), 6, 1e-9);
}

TEST(SetFactory, PhysicalGroupsNameBoxes) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
          "Physical Volume(\"block\", 7) = {1};\n");
  EXPECT_TRUE(run.log.warnings.empty());
  run.session.synchronize();
  const auto& groups = run.session.model().physicalGroups();
  ASSERT_TRUE(groups.contains({3, 7}));
  EXPECT_EQ(groups.at({3, 7}).entities, std::vector<int>{1});
}

TEST(SetFactory, MeshSizesAtTheBoxsPoints) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
          "MeshSize{PointsOf{Volume{1};}} = 0.3;\n");
  EXPECT_TRUE(run.log.warnings.empty());
  run.session.synchronize();
  for (const auto& [tag, point] : run.session.model().points())
    EXPECT_EQ(point.meshSize, 0.3) << "point " << tag;
}

TEST(SetFactory, MeshSizesAtPointsOfBothFactories) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
          "Point(100) = {3, 0, 0};\nMeshSize{1, 100} = 0.2;\n");
  run.session.synchronize();
  EXPECT_EQ(run.session.model().point(1)->meshSize, 0.2);
  EXPECT_EQ(run.session.model().point(100)->meshSize, 0.2);
}

TEST(SetFactory, EntitiesInABoundingBoxOfBothFactories) {
  EXPECT_EQ(printed("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
                    "Point(100) = {0.5, 0.5, 2};\nPoint(101) = {0.5, 0.5, 9};\n"
                    "p() = Point In BoundingBox{-1, -1, 0.5, 2, 2, 3};\n"
                    "s() = Surface In BoundingBox{-1, -1, 0.5, 2, 2, 3};\n"
                    "v() = Volume In BoundingBox{-1, -1, -1, 2, 2, 2};\n"
                    "Printf(\"%g %g %g %g\", #p(), p(#p() - 1), #s(), #v());"),
            "5 100 1 1\n");
}

TEST(SetFactory, BoundaryOfABox) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
          "Box(2) = {1, 0, 0, 1, 1, 1};\n"
          "Physical Surface(\"walls\") = Boundary{Volume{1};};\n"
          "c() = CombinedBoundary{Volume{1}; Volume{2};};\nPrintf(\"%g\", #c());\n");
  EXPECT_TRUE(run.log.warnings.empty());
  EXPECT_EQ(run.out.str(), "12\n");  // the boxes touch but are not glued: no face is shared
  run.session.synchronize();
  EXPECT_EQ(run.session.model().physicalGroups().begin()->second.entities,
            (std::vector<int>{1, 2, 3, 4, 5, 6}));
}

// The older form of Periodic Surface on surfaces of the
// built-in kernel, that kernel carries it out, saying so once.
TEST(SetFactory, BuiltInKernelCarriesOutWhatOpenCascadeCannotYetAndSaysSoOnce) {
  ScriptRun run;
  run.run("For s In {0:1}\n"
          "  For i In {0:3}\n"
          "    Point(4 * s + i + 1) = {2 * s + (i == 1 || i == 2), (i >= 2), 0};\n"
          "  EndFor\n"
          "  For i In {0:3}\n"
          "    Line(4 * s + i + 1) = {4 * s + i + 1, 4 * s + (i + 1) % 4 + 1};\n"
          "  EndFor\n"
          "  Curve Loop(s + 1) = {4 * s + 1 : 4 * s + 4};\n"
          "  Plane Surface(s + 1) = {s + 1};\n"
          "EndFor\n"
          "SetFactory(\"OpenCASCADE\");\n"
          "Periodic Surface 2 {5, 6, 7, 8} = 1 {1, 2, 3, 4};\n"
          "Periodic Surface 2 {5, 6, 7, 8} = 1 {1, 2, 3, 4};\n"
          "Box(1) = {5, 0, 0, 1, 1, 1};\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_EQ(run.log.warnings[0],
            "test.geo:12:1: warning: 'Periodic' is not supported by the OpenCASCADE factory yet; "
            "the built-in kernel carries it out");
  run.session.synchronize();
  ASSERT_TRUE(run.session.model().surface(2)->periodic.has_value());
  EXPECT_EQ(run.session.model().surface(2)->periodic->master, 1);
  EXPECT_EQ(run.session.model().volumes().size(), 1u);
}

// Coherence on the OpenCASCADE model fragments its volumes, as the reference does.
TEST(SetFactory, CoherenceGluesOpenCascadeVolumes) {
  EXPECT_EQ(printed("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
                    "Box(2) = {1, 0, 0, 1, 1, 1};\nCoherence;\n"
                    "s() = Surface{:};\nv() = Volume{:};\nPrintf(\"%g %g\", #s(), #v());\n"),
            "11 2\n");
}

TEST(SetFactory, BothFactoriesShareOneModel) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
          "Point(newp) = {5, 5, 5};\np() = Point{9};\nq() = Point{1};\n"
          "Printf(\"%g %g %g\", newp, p(0), q(2));\n");
  EXPECT_EQ(run.out.str(), "10 5 1\n");  // the box's first point is (0, 0, 1)
  run.session.synchronize();
  EXPECT_EQ(run.session.model().points().size(), 9u);
  EXPECT_EQ(run.session.model().volumes().size(), 1u);
}

TEST(SetFactory, BuiltInSwitchesBack) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nSetFactory(\"Built-in\");\n"
          "Point(1) = {0, 0, 0};\nBox(1) = {0, 0, 0, 1, 1, 1};\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_EQ(run.log.warnings[0],
            "test.geo:4:1: warning: 'Box' needs SetFactory(\"OpenCASCADE\"); ignored");
  run.session.synchronize();
  EXPECT_EQ(run.session.model().points().size(), 1u);
  EXPECT_TRUE(run.session.model().volumes().empty());
}

TEST(SetFactory, BoxErrorsPointAtTheStatement) {
  EXPECT_EQ(firstLineOf("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 0, 1};"),
            "test.geo:2:1: error: Box 1 has a zero extent");
  EXPECT_EQ(firstLineOf("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1};"),
            "test.geo:2:10: error: Box takes {x, y, z, dx, dy, dz}, not 4 values");
}

}  // namespace
}  // namespace geomesh::testing
