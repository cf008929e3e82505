// Closed surfaces of merged mesh files (STL, ...) as discrete surfaces: volumes bounded by
// them, their groups, and what cannot be done with them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "api/meshing.h"
#include "mesh/core/quality.h"
#include "mesh_measures.h"
#include "script_runner.h"
#include "scratch_dir_test.h"

namespace geomesh::testing {
namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

class DiscreteSurfaces : public ScratchDirTest {
 protected:
  DiscreteSurfaces() : ScratchDirTest("discrete-") {}

  // Two concentric spheres (radii 1 and 0.4) written as an STL file of two solids.
  void writeSpheres() {
    ScriptRun make;
    runMain(make, R"(
      SetFactory("OpenCASCADE");
      Sphere(1) = {0, 0, 0, 1};
      Sphere(2) = {0, 0, 0, 0.4};
      Mesh.MeshSizeMax = 0.15;
      Mesh 2;
      Save "spheres.stl";
    )");
  }

};

// The volume a closed surface's triangles enclose (divergence theorem), whatever their
// orientation.
double enclosed(const Mesh& mesh, int surface) {
  const ElementBlock* t = mesh.find({2, surface})->findBlock(ElementType::Triangle3);
  double v = 0;
  for (std::size_t e = 0; e < t->size(); ++e) {
    const auto n = t->element(e);
    v += dot(mesh.node(n[0]), cross(mesh.node(n[1]), mesh.node(n[2])));
  }
  return std::abs(v) / 6;
}

TEST_F(DiscreteSurfaces, VolumesBetweenMergedSurfacesAreMeshedAndKeepTheirTriangles) {
  writeSpheres();
  ScriptRun plain;
  runMain(plain, "Merge \"spheres.stl\";\n");
  const std::size_t triangles = count(plain.session.mesh(), ElementType::Triangle3);
  ASSERT_GT(triangles, 1000u);

  ScriptRun run;
  runMain(run, R"(
    Merge "spheres.stl";
    Surface Loop(1) = {1};
    Surface Loop(2) = {2};
    Volume(1) = {1, 2};
    Volume(2) = {2};
    Physical Surface("skin") = {1};
    Physical Volume("shell") = {1};
    Physical Volume("core") = {2};
  )");
  api::generate(run.session, 3);
  const Mesh& mesh = run.session.mesh();
  EXPECT_EQ(count(mesh, ElementType::Triangle3), triangles);  // the file's, not remeshed
  EXPECT_GT(count(mesh, ElementType::Tet4), 2000u);
  // The tetrahedra fill exactly what the file's triangles enclose: polyhedra inscribed in
  // the spheres, a little below 4/3 pi r^3.
  const double outer = enclosed(mesh, 1), inner = enclosed(mesh, 2);
  EXPECT_NEAR(measure(mesh, 3, {3, 2}), inner, 1e-9);
  EXPECT_NEAR(measure(mesh, 3, {3, 1}), outer - inner, 1e-9);
  EXPECT_LT(outer, 4 * kPi / 3);
  EXPECT_GT(outer, 0.95 * 4 * kPi / 3);
  const QualityStats q = meshQuality(mesh, 3, QualityMeasure::Gamma);
  EXPECT_GT(q.min, 0.1);
  EXPECT_EQ(run.session.model().physicalGroups().size(), 3u);
}

TEST_F(DiscreteSurfaces, AMergeAloneKeepsTheFileAsItIs) {
  writeSpheres();
  ScriptRun run;
  runMain(run, "Merge \"spheres.stl\";\n");
  const std::size_t before = run.session.mesh().elementCount(2);
  api::generate(run.session, 3);
  EXPECT_EQ(run.session.mesh().elementCount(2), before);
  EXPECT_EQ(run.session.mesh().elementCount(3), 0u);
}

TEST_F(DiscreteSurfaces, AnOpenSurfaceCannotBoundAVolume) {
  ScriptRun make;
  runMain(make, R"(
    Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25};
    Point(3) = {1, 1, 0, 0.25}; Point(4) = {0, 1, 0, 0.25};
    Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
    Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
    Mesh 2;
    Save "plate.stl";
  )");
  ScriptRun run;
  runMain(run, "Merge \"plate.stl\";\nSurface Loop(1) = {1};\nVolume(1) = {1};\n");
  try {
    api::generate(run.session, 3);
    FAIL() << "an open surface bounded a volume";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("do not close"), std::string::npos) << e.what();
  }
}

TEST_F(DiscreteSurfaces, MovingOrExtrudingThemIsAnError) {
  writeSpheres();
  for (const char* statement :
       {"Translate {1, 0, 0} { Surface{1}; }", "Extrude {0, 0, 1} { Surface{1}; }",
        "Duplicata { Surface{2}; }"}) {
    ScriptRun run;
    try {
      runMain(run, std::string("Merge \"spheres.stl\";\n") + statement + "\n");
      FAIL() << statement;
    } catch (const ScriptError& e) {
      EXPECT_NE(std::string(e.what()).find("merged mesh file"), std::string::npos) << e.what();
    }
  }
}

TEST_F(DiscreteSurfaces, TheUnrolledScriptMergesTheFileAgain) {
  writeSpheres();
  const std::string script =
      "Merge \"spheres.stl\";\nSurface Loop(1) = {2};\nVolume(1) = {1};\n";
  ScriptRun first;
  runMain(first, script + "Save \"again.geo_unrolled\";\n");
  api::generate(first.session, 3);
  ScriptRun again;
  again.run("Merge \"again.geo_unrolled\";\n", (dir_ / "replay.geo").string());
  api::generate(again.session, 3);
  EXPECT_GT(again.session.mesh().elementCount(3), 0u);
  EXPECT_EQ(again.session.mesh().elementCount(3), first.session.mesh().elementCount(3));
  EXPECT_NEAR(measure(again.session.mesh(), 3), measure(first.session.mesh(), 3), 1e-12);
}

TEST_F(DiscreteSurfaces, TheOpenCascadeFactoryHandsTheirVolumesToTheBuiltInOne) {
  writeSpheres();
  ScriptRun run;
  runMain(run, "SetFactory(\"OpenCASCADE\");\nMerge \"spheres.stl\";\n"
               "Surface Loop(1) = {2};\nVolume(1) = {1};\n");
  api::generate(run.session, 3);
  EXPECT_NEAR(measure(run.session.mesh(), 3), enclosed(run.session.mesh(), 2), 1e-9);
}

}  // namespace
}  // namespace geomesh::testing
