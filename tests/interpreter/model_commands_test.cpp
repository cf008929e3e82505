// Statements acting on the whole model while a script runs: Mesh n, Save, Merge, Delete Model,
// NewModel, Delete Variables / Options / name, and Printf's dependence on the verbosity.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "io/msh_reader.h"
#include "mesh/core/quality.h"
#include "script_runner.h"
#include "tests/scratch.h"

namespace geomesh::testing {
namespace {

namespace fs = std::filesystem;

const char* kUnitSquare = R"(
Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 1, 0, 0.25}; Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
)";

class ModelCommands : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch::path(
        "model-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `text` as main.geo in the scratch directory.
  std::string runMain(ScriptRun& run, const std::string& text) {
    return run.run(text, (dir_ / "main.geo").string());
  }
  std::string read(const std::string& name) const {
    std::ifstream in(dir_ / name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  fs::path dir_;
};

double triangleArea(const Mesh& mesh) {
  double area = 0;
  for (const auto& [entity, part] : mesh.entities()) {
    const ElementBlock* block = part.findBlock(ElementType::Triangle3);
    if (!block) continue;
    for (std::size_t e = 0; e < block->size(); ++e)
      area += elementMeasure(mesh, ElementType::Triangle3,
                             std::span(block->nodes).subspan(3 * e, 3));
  }
  return area;
}

TEST_F(ModelCommands, MeshInAScriptMeshesTheModelAsItStands) {
  ScriptRun run;
  const std::string out = runMain(run, std::string(kUnitSquare) + R"(
Mesh 1;
Printf("after 1D: %g", 1);
Mesh 2;
Printf("meshed");
)");
  EXPECT_EQ(out, "after 1D: 1\nmeshed\n");
  const Mesh& mesh = run.session.mesh();
  EXPECT_GT(mesh.elementCount(2), 20u);
  EXPECT_GT(mesh.elementCount(1), 12u);
  EXPECT_NEAR(triangleArea(mesh), 1.0, 1e-12);
}

// Read-only options follow the model and the mesh, as in Gmsh.
TEST_F(ModelCommands, StatisticsOptionsDescribeTheModelAndTheMesh) {
  ScriptRun run;
  const std::string out = runMain(run, std::string(kUnitSquare) + R"(
Printf("%g %g | %g %g %g %g %.6g", Mesh.NbNodes, Mesh.NbTriangles, General.MinX, General.MaxX,
       General.MinY, General.MaxY, General.BoundingBoxSize);
Mesh 2;
Printf("%g %g %g", Mesh.NbNodes, Mesh.NbTriangles, Mesh.NbQuadrangles);
)");
  const auto triangles = run.session.mesh().elementCount(2);
  EXPECT_EQ(out, "0 0 | 0 1 0 1 1.41421\n" + std::to_string(run.session.mesh().nodeCount()) + " " +
                     std::to_string(triangles) + " 0\n");
  EXPECT_GT(triangles, 20u);
}

// A generated mesh has no duplicate nodes: Coherence Mesh keeps it as it is.
TEST_F(ModelCommands, CoherenceMeshOnAGeneratedMesh) {
  ScriptRun run;
  const std::string out = runMain(
      run, std::string(kUnitSquare) + "Mesh 2;\nn = Mesh.NbNodes;\nCoherence Mesh;\n"
                                      "Printf(\"%g\", Mesh.NbNodes - n);\n");
  EXPECT_EQ(out, "0\n");
  EXPECT_TRUE(run.log.warnings.empty());
}

TEST_F(ModelCommands, MeshTakesADimensionFromZeroToThree) {
  ScriptRun run;
  EXPECT_THROW(runMain(run, std::string(kUnitSquare) + "Mesh 4;"), ScriptError);
}

TEST_F(ModelCommands, SaveWritesTheMeshNextToTheScript) {
  ScriptRun run;
  runMain(run, std::string(kUnitSquare) + "Mesh 2;\nSave \"out.msh\";\n");
  ASSERT_TRUE(fs::exists(dir_ / "out.msh"));
  Model model;
  Mesh mesh;
  readMshFile((dir_ / "out.msh").string(), model, mesh);
  EXPECT_EQ(mesh.nodeCount(), run.session.mesh().nodeCount());
  EXPECT_EQ(mesh.elementCount(2), run.session.mesh().elementCount(2));
  EXPECT_NEAR(triangleArea(mesh), 1.0, 1e-12);
  EXPECT_FALSE(fs::exists(dir_ / "out.msh.partial"));
}

TEST_F(ModelCommands, SaveIntoAMissingDirectoryIsALocatedError) {
  ScriptRun run;
  try {
    runMain(run, std::string(kUnitSquare) + "Mesh 2;\nSave \"no/such/dir/out.msh\";\n");
    FAIL() << "no error";
  } catch (const ScriptError& error) {
    EXPECT_EQ(error.location().line, 7);
    EXPECT_NE(error.message().find("cannot write"), std::string::npos) << error.message();
  }
  EXPECT_FALSE(fs::exists(dir_ / "no"));
}

TEST_F(ModelCommands, SaveFollowsTheMshVersionOption) {
  ScriptRun run;
  runMain(run, std::string(kUnitSquare) +
                   "Mesh 2;\nMesh.MshFileVersion = 2.2;\nSave StrCat(\"old\", \".msh\");\n");
  EXPECT_EQ(read("old.msh").rfind("$MeshFormat\n2.2 0 8\n", 0), 0u) << read("old.msh");
}

TEST_F(ModelCommands, SaveOptionsListsOnlyTheChangedOnes) {
  ScriptRun run;
  runMain(run, "Mesh.MeshSizeMax = 0.5;\nGeometry.Tolerance = 1e-6;\nSave \"o.opt\";\n");
  const std::string text = read("o.opt");
  EXPECT_NE(text.find("Mesh.MeshSizeMax = 0.5;"), std::string::npos) << text;
  EXPECT_NE(text.find("Geometry.Tolerance = 1e-06;"), std::string::npos) << text;
  EXPECT_EQ(text.find("Mesh.Algorithm ="), std::string::npos) << text;
}

TEST_F(ModelCommands, SaveUnrolledGeometry) {
  ScriptRun run;
  runMain(run, std::string(kUnitSquare) + "Save \"flat.geo_unrolled\";\n");
  const std::string text = read("flat.geo_unrolled");
  EXPECT_NE(text.find("Plane Surface(1)"), std::string::npos) << text;
}

TEST_F(ModelCommands, SaveInAnUnwrittenFormatWarnsAndWritesNothing) {
  ScriptRun run;
  runMain(run, std::string(kUnitSquare) + "Mesh 2;\nSave \"out.wrl\";\nPrint \"shot.eps\";\n");
  EXPECT_FALSE(fs::exists(dir_ / "out.wrl"));
  EXPECT_FALSE(fs::exists(dir_ / "shot.eps"));
  ASSERT_EQ(run.log.warnings.size(), 2u);
  EXPECT_NE(run.log.warnings[0].find("cannot write"), std::string::npos);
  EXPECT_NE(run.log.warnings[0].find("out.wrl"), std::string::npos);
}

TEST_F(ModelCommands, PrintWritesAPictureOfTheMeshOfTheSizeTheScriptSets) {
  ScriptRun run;
  runMain(run, std::string(kUnitSquare) +
                   "Mesh 2;\nPrint.Width = 64; Print.Height = 48;\nPrint \"shot.png\";\n"
                   "Printf(\"%g\", Print.Width);\nSave \"shot.svg\";\n");
  EXPECT_EQ(run.out.str(), "64\n");
  EXPECT_TRUE(run.log.warnings.empty());
  EXPECT_NE(read("shot.svg").find("width=\"64\" height=\"48\""), std::string::npos);
  const std::string png = read("shot.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_EQ(static_cast<unsigned char>(png[19]), 64u);  // IHDR width, big-endian
  EXPECT_EQ(static_cast<unsigned char>(png[23]), 48u);  // IHDR height
}

TEST_F(ModelCommands, SaveWritesEveryFormatOfTheTable) {
  ScriptRun run;
  runMain(run, std::string(kUnitSquare) + "Mesh 2;\nSave \"out.vtk\";\n");
  EXPECT_EQ(read("out.vtk").rfind("# vtk DataFile Version 2.0\n", 0), 0u) << read("out.vtk");
  EXPECT_NE(read("out.vtk").find("DATASET UNSTRUCTURED_GRID\n"), std::string::npos);
}

TEST_F(ModelCommands, MergeReadsAScriptLikeInclude) {
  std::ofstream(dir_ / "part.geo") << "b = a + 1;\nPrintf(\"in part\");\n";
  ScriptRun run;
  EXPECT_EQ(runMain(run, "a = 1;\nMerge \"part.geo\";\nPrintf(\"b=%g\", b);\n"),
            "in part\nb=2\n");
}

TEST_F(ModelCommands, MergeReadsOptionFilesAndUnrolledGeometry) {
  std::ofstream(dir_ / "o.opt") << "Mesh.MeshSizeMax = 0.3;\nGeometry.Tolerance = 1e-5;\n";
  ScriptRun run;
  EXPECT_EQ(runMain(run, R"(
Merge "o.opt";
Printf("%g %g", Mesh.MeshSizeMax, Geometry.Tolerance);
Point(1) = {0, 0, 0};
Save "u.geo_unrolled";
Delete Model;
Merge "u.geo_unrolled";
Printf("%g", newp);
)"),
            "0.3 1e-05\n2\n");
}

TEST_F(ModelCommands, MergeReadsAMeshThatMeshingThenKeeps) {
  {
    ScriptRun first;
    runMain(first, std::string(kUnitSquare) + "Mesh 2;\nSave \"square.msh\";\n");
  }
  ScriptRun run;
  runMain(run, "Merge \"square.msh\";\nMesh 2;\nSave \"copy.msh\";\n");
  EXPECT_TRUE(run.log.warnings.empty());
  EXPECT_GT(run.session.mesh().elementCount(2), 20u);
  EXPECT_NEAR(triangleArea(run.session.mesh()), 1.0, 1e-12);
  Model model;
  Mesh mesh;
  readMshFile((dir_ / "copy.msh").string(), model, mesh);
  EXPECT_EQ(mesh.nodeCount(), run.session.mesh().nodeCount());
  EXPECT_EQ(mesh.elementCount(2), run.session.mesh().elementCount(2));
}

TEST_F(ModelCommands, MergeReadsMsh1And3Files) {
  const std::string nodes = "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n";
  std::ofstream(dir_ / "v1.msh") << "$NOD\n4\n" << nodes << "$ENDNOD\n$ELM\n2\n"
                                 << "1 2 10 7 3 1 2 3\n2 2 10 7 3 1 3 4\n$ENDELM\n";
  std::ofstream(dir_ / "v3.msh") << "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n$Nodes\n4\n" << nodes
                                 << "$EndNodes\n$Elements\n2\n1 2 2 10 7 1 2 3\n"
                                 << "2 2 2 10 7 1 3 4\n$EndElements\n";
  for (const char* file : {"v1.msh", "v3.msh"}) {
    ScriptRun run;
    runMain(run, "Merge \"" + std::string(file) + "\";\n");
    EXPECT_EQ(run.session.mesh().elementCount(2), 2u) << file;
    EXPECT_NEAR(triangleArea(run.session.mesh()), 1.0, 1e-12) << file;
  }
}

TEST_F(ModelCommands, MergeReadsTheOtherMeshFormatsOfTheTable) {
  {
    ScriptRun first;
    runMain(first, std::string(kUnitSquare) +
                       "Mesh 2;\nSave \"square.vtk\";\nSave \"square.stl\";\n"
                       "Save \"square.ply\";\nSave \"square.off\";\nSave \"square.cgns\";\n");
  }
  for (const char* file :
       {"square.vtk", "square.stl", "square.ply", "square.off", "square.cgns"}) {
    ScriptRun run;
    runMain(run, "Merge \"" + std::string(file) + "\";\n");
    EXPECT_TRUE(run.log.warnings.empty()) << file;
    EXPECT_GT(run.session.mesh().elementCount(2), 20u) << file;
    EXPECT_NEAR(triangleArea(run.session.mesh()), 1.0, 1e-12) << file;
  }
}

TEST_F(ModelCommands, MergeOfAMeshBesideGeometryIsRefused) {
  {
    ScriptRun first;
    runMain(first, std::string(kUnitSquare) + "Mesh 2;\nSave \"square.msh\";\n");
  }
  ScriptRun before;
  runMain(before, "Point(1) = {0, 0, 0};\nMerge \"square.msh\";\n");
  ASSERT_EQ(before.log.warnings.size(), 1u);
  EXPECT_NE(before.log.warnings[0].find("already has geometry"), std::string::npos);
  EXPECT_EQ(before.session.mesh().nodeCount(), 0u);
  ScriptRun after;
  EXPECT_THROW(runMain(after, "Merge \"square.msh\";\nPoint(1) = {0, 0, 0};\nMesh 2;\n"),
               ScriptError);
}

TEST_F(ModelCommands, MergeOfOtherFilesWarnsAndMissingMeshesFail) {
  ScriptRun run;
  runMain(run, "Merge \"surface.wrl\";\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_NE(run.log.warnings[0].find("'Merge' of 'surface.wrl' is not supported yet"),
            std::string::npos);
  ScriptRun missing;
  EXPECT_THROW(runMain(missing, "Merge \"nothing.msh\";\n"), ScriptError);
}

TEST_F(ModelCommands, DeleteModelAndNewModelStartAfresh) {
  ScriptRun run;
  const std::string out = runMain(run, std::string(kUnitSquare) + R"(
x = 5;
Mesh 2;
Delete Model;
Printf("%g %g %g x=%g", newp, newl, news, x);
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Line(7) = {1, 2};
NewModel;
Printf("%g %g", newp, newl);
Point(3) = {0, 0, 0};
Delete All;
Printf("%g", newp);
)");
  EXPECT_EQ(out, "1 1 1 x=5\n1 1\n1\n");
  EXPECT_EQ(run.session.mesh().nodeCount(), 0u);
}

TEST_F(ModelCommands, DeleteVariablesAndOneVariable) {
  ScriptRun run;
  EXPECT_EQ(runMain(run, R"(
x = 5; y[] = {1, 2}; z = 3;
Delete z;
Printf("%g %g %g", Exists(x), Exists(y), Exists(z));
Delete Variables;
Printf("%g %g", Exists(x), Exists(y));
)"),
            "1 1 0\n0 0\n");
}

TEST_F(ModelCommands, DeleteOptionsRestoresTheDefaults) {
  ScriptRun run;
  EXPECT_EQ(
      runMain(run, "Mesh.MeshSizeMax = 3;\nDelete Options;\nPrintf(\"%g\", Mesh.MeshSizeMax);\n"),
      "1e+22\n");
}

// Script output is a "direct" message: at verbosity 2 and below it is not shown, but Printf
// into a file still writes.
TEST_F(ModelCommands, PrintfFollowsTheVerbosity) {
  ScriptRun run;
  run.session.options().setNumber("General.Verbosity", 2);
  EXPECT_EQ(runMain(run, "Printf(\"shown?\");\nPrintf(\"kept %g\", 1) > \"p.txt\";\n"), "");
  EXPECT_EQ(read("p.txt"), "kept 1\n");
  ScriptRun loud;
  loud.session.options().setNumber("General.Verbosity", 3);
  EXPECT_EQ(runMain(loud, "Printf(\"shown\");\n"), "shown\n");
}

TEST_F(ModelCommands, ASandboxedSessionNeitherWritesNorMeshes) {
  ScriptRun run;
  run.session.setSandboxed(true);
  runMain(run, std::string(kUnitSquare) +
                   "Mesh 2;\nSave \"out.msh\";\nPrint \"out.opt\";\n"
                   "Printf(\"x\") > \"out.txt\";\nPrintf(\"done\");\n");
  EXPECT_EQ(run.out.str(), "done\n");
  EXPECT_EQ(run.session.mesh().nodeCount(), 0u);
  EXPECT_TRUE(fs::is_empty(dir_));
  ASSERT_EQ(run.log.warnings.size(), 4u);
  EXPECT_NE(run.log.warnings[0].find("main.geo:6:1: warning: 'Mesh' skipped"), std::string::npos)
      << run.log.warnings[0];
  EXPECT_NE(run.log.warnings[3].find("Printf into 'out.txt' skipped"), std::string::npos)
      << run.log.warnings[3];
}

TEST_F(ModelCommands, IncludeAndListFromFileReadOnlyRegularFiles) {
  // A device would be read forever; a directory has no text.
  EXPECT_NE(firstLineOf("Include \"/dev/zero\";").find("cannot open include file '/dev/zero'"),
            std::string::npos);
  EXPECT_NE(firstLineOf("Include \"/tmp\";").find("cannot open include file '/tmp'"),
            std::string::npos);
  EXPECT_NE(firstLineOf("x() = ListFromFile(\"/dev/zero\");").find("cannot open '/dev/zero'"),
            std::string::npos);
}

}  // namespace
}  // namespace geomesh::testing

namespace geomesh::testing {
namespace {

// A CAD file merged by a script meshes: its cylindrical bore closes on a seam.
class CadImport : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch::path(
        "cad-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    fs::copy_file(fs::path(GEOMESH_SOURCE_DIR) / "tutorials" / "part.step", dir_ / "part.step");
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string runMain(ScriptRun& run, const std::string& text) {
    return run.run(text, (dir_ / "main.geo").string());
  }
  fs::path dir_;
};

TEST_F(CadImport, MergedStepPartMeshesToItsArea) {
  ScriptRun run;
  runMain(run, "Merge \"part.step\";\nMesh.MeshSizeMax = 0.1;\nMesh 2;\n");
  EXPECT_TRUE(run.log.warnings.empty());
  const Model& model = run.session.model();
  EXPECT_EQ(model.volumes().size(), 1u);
  EXPECT_EQ(model.surfaces().size(), 7u);
  const double pi = std::numbers::pi;
  EXPECT_NEAR(triangleArea(run.session.mesh()), 2 * (4 - 0.16 * pi) + 4 + 0.4 * pi, 0.02);
}

}  // namespace
}  // namespace geomesh::testing
