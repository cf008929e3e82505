// Merged triangulations classified into surfaces, curves and points (ClassifySurfaces,
// CreateTopology), then given geometry and meshed anew (CreateGeometry).
#include <gtest/gtest.h>

#include <algorithm>
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

class ClassifiedSurfaces : public ScratchDirTest {
 protected:
  ClassifiedSurfaces() : ScratchDirTest("classified-") {}

  // The surface mesh of an OpenCASCADE solid, saved as `file` (an STL of one solid).
  void writeStl(const std::string& solid, const std::string& file, double size) {
    ScriptRun make;
    runMain(make, "SetFactory(\"OpenCASCADE\");\n" + solid + "\nMesh.MeshSizeMax = " +
                  std::to_string(size) + ";\nMesh 2;\nSave \"" + file + "\";\n");
  }
  // Merges the file, classifies it, creates the geometry and fills it: the session, meshed.
  void remesh(ScriptRun& session, const std::string& file, const std::string& extra = "") {
    runMain(session, "Merge \"" + file + "\";\nClassifySurfaces{40 * Pi / 180, 1, 0, Pi};\n" +
                     "CreateGeometry;\nSurface Loop(1) = Surface{:};\nVolume(1) = {1};\n" + extra);
    api::generate(session.session, 3);
  }
};

// The volume the triangles of every surface enclose (divergence theorem), of either sign.
double enclosed(const Mesh& mesh) {
  double v = 0;
  for (const auto& [id, em] : mesh.entities()) {
    const ElementBlock* t = id.dim == 2 ? em.findBlock(ElementType::Triangle3) : nullptr;
    for (std::size_t e = 0; t && e < t->size(); ++e) {
      const auto n = t->element(e);
      v += dot(mesh.node(n[0]), cross(mesh.node(n[1]), mesh.node(n[2])));
    }
  }
  return std::abs(v) / 6;
}

// Area and enclosed volume of the merged file as it is.
std::pair<double, double> fileMeasures(const fs::path& file) {
  ScriptRun plain;
  plain.run("Merge \"" + file.filename().string() + "\";\n", (file.parent_path() / "m.geo").string());
  return {measure(plain.session.mesh(), 2), enclosed(plain.session.mesh())};
}

TEST_F(ClassifiedSurfaces, ABoxSplitsIntoItsSixFaces) {
  writeStl("Box(1) = {0, 0, 0, 1, 2, 3};", "box.stl", 0.2);
  ScriptRun session;
  runMain(session, "Merge \"box.stl\";\nClassifySurfaces{40 * Pi / 180, 1, 0, Pi};\n");
  session.session.synchronize();
  const Model& model = session.session.model();
  EXPECT_EQ(model.points().size(), 8u);
  EXPECT_EQ(model.curves().size(), 12u);
  ASSERT_EQ(model.surfaces().size(), 6u);
  // The file holds one solid per face (surfaces 1 to 6): they are replaced by surfaces
  // numbered on from them.
  EXPECT_EQ(model.surfaces().begin()->first, 7);
  for (const auto& [tag, surface] : model.surfaces()) {
    ASSERT_EQ(surface.loops.size(), 1u);
    EXPECT_EQ(surface.loops[0].size(), 4u);
    EXPECT_TRUE(surface.discrete);
  }
  for (const auto& [tag, curve] : model.curves()) {
    EXPECT_TRUE(curve.discrete);
    // Each edge of the box, whole: from one corner to another, 1, 2 or 3 long.
    const double length = distance(model.point(curve.startPoint)->xyz,
                                   model.point(curve.endPoint)->xyz);
    EXPECT_NEAR(length, std::round(length), 1e-9);
  }
}

// A surface mesh saved with its curves and points (MSH, Medit, VTK): merged as it is, and its
// surfaces taken as merged triangles once ClassifySurfaces asks for them.
TEST_F(ClassifiedSurfaces, SurfaceMeshFilesWithCurvesAreClassifiedToo) {
  for (const char* file : {"box.msh", "box.mesh", "box.vtk"}) {
    writeStl("Box(1) = {0, 0, 0, 1, 2, 3};", file, 0.25);
    ScriptRun kept;
    runMain(kept, std::string("Merge \"") + file + "\";\n");
    EXPECT_GT(count(kept.session.mesh(), ElementType::Line2), 0u) << file;  // as it was read
    ScriptRun session;
    remesh(session, file, "Mesh.MeshSizeMax = 0.3;\n");
    const Mesh& mesh = session.session.mesh();
    EXPECT_EQ(session.session.model().surfaces().size(), 6u) << file;
    EXPECT_NEAR(measure(mesh, 3), 6, 1e-9) << file;
    EXPECT_NEAR(measure(mesh, 2), 22, 1e-9) << file;
    const std::string said = "its 6 surfaces are taken as merged triangles; its 12 curves, ";
    const auto& infos = session.log.infos;
    EXPECT_TRUE(std::any_of(infos.begin(), infos.end(), [&](const std::string& m) {
      return m.find(said) != std::string::npos;
    })) << file;
  }
}

TEST_F(ClassifiedSurfaces, WithoutCreateGeometryTheTrianglesAreKept) {
  writeStl("Box(1) = {0, 0, 0, 1, 2, 3};", "box.stl", 0.2);
  ScriptRun plain;
  runMain(plain, "Merge \"box.stl\";\n");
  const std::size_t triangles = count(plain.session.mesh(), ElementType::Triangle3);
  ScriptRun session;
  runMain(session, "Merge \"box.stl\";\nClassifySurfaces{40 * Pi / 180, 1, 0, Pi};\n");
  api::generate(session.session, 2);
  const Mesh& mesh = session.session.mesh();
  EXPECT_EQ(count(mesh, ElementType::Triangle3), triangles);
  EXPECT_EQ(count(mesh, ElementType::Point1), 8u);
  // The curves' segments are the triangles' edges along the box's 12 edges (24 long).
  EXPECT_NEAR(measure(mesh, 1), 24, 1e-9);
  EXPECT_NEAR(measure(mesh, 2), 22, 1e-9);
}

TEST_F(ClassifiedSurfaces, CreateGeometryRemeshesABoxAtTheSizeAsked) {
  writeStl("Box(1) = {0, 0, 0, 1, 2, 3};", "box.stl", 0.5);
  ScriptRun session;
  remesh(session, "box.stl", "Mesh.MeshSizeMax = 0.1;\n");
  const Mesh& mesh = session.session.mesh();
  EXPECT_NEAR(measure(mesh, 3), 6, 1e-9);
  EXPECT_NEAR(measure(mesh, 2), 22, 1e-9);
  EXPECT_NEAR(measure(mesh, 1), 24, 1e-9);
  // Remeshed five times finer than the file: about 22 / (0.1^2 sqrt(3) / 4) triangles.
  const double expected = 22 / (0.01 * std::sqrt(3.0) / 4);
  EXPECT_GT(static_cast<double>(count(mesh, ElementType::Triangle3)), 0.6 * expected);
  EXPECT_LT(static_cast<double>(count(mesh, ElementType::Triangle3)), 1.6 * expected);
  EXPECT_GT(meshQuality(mesh, 3, QualityMeasure::Gamma).min, 0.1);
  EXPECT_GT(meshQuality(mesh, 2, QualityMeasure::Gamma).min, 0.5);
}

TEST_F(ClassifiedSurfaces, ACylinderSideIsMappedAroundItsHole) {
  writeStl("Cylinder(1) = {0, 0, 0, 0, 0, 2, 0.5};", "cylinder.stl", 0.08);
  const auto [area, volume] = fileMeasures(dir_ / "cylinder.stl");
  ScriptRun session;
  remesh(session, "cylinder.stl", "Mesh.MeshSizeMax = 0.12;\n");
  const Model& model = session.session.model();
  EXPECT_EQ(model.surfaces().size(), 3u);
  EXPECT_EQ(model.curves().size(), 2u);
  const Mesh& mesh = session.session.mesh();
  // The new nodes lie on the file's triangles: the remeshed area is the file's; coarser
  // triangles cut across the file's facets, which takes a little of the volume.
  EXPECT_NEAR(measure(mesh, 2), area, 0.005 * area);
  EXPECT_NEAR(measure(mesh, 3), volume, 0.015 * volume);
  EXPECT_LT(measure(mesh, 3), volume);
  EXPECT_GT(meshQuality(mesh, 3, QualityMeasure::Gamma).min, 0.1);
  EXPECT_GT(meshQuality(mesh, 2, QualityMeasure::Gamma).min, 0.3);
}

TEST_F(ClassifiedSurfaces, AClosedSphereIsSplitUntilItMaps) {
  writeStl("Sphere(1) = {0, 0, 0, 1};", "sphere.stl", 0.1);
  const auto [area, volume] = fileMeasures(dir_ / "sphere.stl");
  ScriptRun session;
  remesh(session, "sphere.stl", "Mesh.MeshSizeMax = 0.15;\n");
  EXPECT_GE(session.session.model().surfaces().size(), 2u);
  const Mesh& mesh = session.session.mesh();
  EXPECT_NEAR(measure(mesh, 2), area, 0.005 * area);
  EXPECT_NEAR(measure(mesh, 3), volume, 0.015 * volume);
  EXPECT_GT(volume, 0.97 * 4 * kPi / 3);
  EXPECT_GT(meshQuality(mesh, 2, QualityMeasure::Gamma).min, 0.3);
}

TEST_F(ClassifiedSurfaces, ATorusWithItsHandleIsSplitUntilEveryPartMaps) {
  writeStl("Torus(1) = {0, 0, 0, 1, 0.3};", "torus.stl", 0.08);
  const auto [area, volume] = fileMeasures(dir_ / "torus.stl");
  ScriptRun session;
  remesh(session, "torus.stl", "Mesh.MeshSizeMax = 0.1;\n");
  EXPECT_GE(session.session.model().surfaces().size(), 3u);
  const Mesh& mesh = session.session.mesh();
  EXPECT_NEAR(measure(mesh, 2), area, 0.005 * area);
  EXPECT_NEAR(measure(mesh, 3), volume, 0.015 * volume);
  // The cuts follow the file's edges, whose zigzag gives the curves uneven segments: the
  // triangles along them are the worst, but none is flat and no tetrahedron is inverted.
  EXPECT_GT(meshQuality(mesh, 2, QualityMeasure::Gamma).min, 0.15);
  EXPECT_GT(meshQuality(mesh, 3, QualityMeasure::Gamma).min, 0.0);
}

TEST_F(ClassifiedSurfaces, CreateTopologyKeepsTheMergedSurfacesApart) {
  ScriptRun make;
  runMain(make, R"(
    SetFactory("OpenCASCADE");
    Sphere(1) = {0, 0, 0, 1};
    Sphere(2) = {3, 0, 0, 1};
    Mesh.MeshSizeMax = 0.2;
    Mesh 2;
    Save "two.stl";
  )");
  ScriptRun session;
  runMain(session, "Merge \"two.stl\";\nCreateTopology;\n");
  session.session.synchronize();
  // One surface per connected part, no curve: both spheres are closed.
  EXPECT_EQ(session.session.model().surfaces().size(), 2u);
  EXPECT_TRUE(session.session.model().curves().empty());
}

TEST_F(ClassifiedSurfaces, FlippedTrianglesAreTurnedWithAWarning) {
  writeStl("Box(1) = {0, 0, 0, 1, 1, 1};", "box.stl", 0.25);
  ScriptRun session;
  remesh(session, "box.stl");
  // OpenCASCADE's faces of a box do not all face out: their triangles disagree in the file.
  bool warned = false;
  for (const std::string& w : session.log.warnings)
    warned = warned || w.find("turned to agree") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_NEAR(measure(session.session.mesh(), 3), 1, 1e-9);
}

TEST_F(ClassifiedSurfaces, WithoutMergedTrianglesItIsALocatedError) {
  ScriptRun session;
  try {
    runMain(session, "Point(1) = {0, 0, 0};\nClassifySurfaces{Pi / 4, 1, 0};\n");
    FAIL() << "classified nothing";
  } catch (const ScriptError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("main.geo:2:"), std::string::npos) << what;
    EXPECT_NE(what.find("no merged triangles"), std::string::npos) << what;
  }
}

TEST_F(ClassifiedSurfaces, TheUnrolledScriptRepeatsTheStatements) {
  writeStl("Cylinder(1) = {0, 0, 0, 0, 0, 2, 0.5};", "cylinder.stl", 0.1);
  ScriptRun first;
  remesh(first, "cylinder.stl", "Save \"again.geo_unrolled\";\n");
  ScriptRun again;
  again.run("Merge \"again.geo_unrolled\";\n", (dir_ / "replay.geo").string());
  api::generate(again.session, 3);
  EXPECT_EQ(again.session.model().surfaces().size(), 3u);
  EXPECT_EQ(again.session.mesh().elementCount(3), first.session.mesh().elementCount(3));
  EXPECT_NEAR(measure(again.session.mesh(), 3), measure(first.session.mesh(), 3), 1e-12);
}

}  // namespace
}  // namespace geomesh::testing
