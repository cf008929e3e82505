// The geomesh command as a user runs it: exit statuses, where output goes, which files appear.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <sys/wait.h>

#include "app/run.h"
#include "command_fixture.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh {
namespace {

// A scratch directory per test, removed afterwards.
class Cli : public CommandTest {
 protected:
  Cli() : CommandTest("cli-") {}
};

const char* kSquare = R"(Point(1) = {0, 0, 0, 0.25};
Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 1, 0, 0.25};
Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Printf("square ready");
)";

TEST_F(Cli, DefaultOutputIsTheScriptNameWithMsh) {
  fs::path geo = write("plate.geo", kSquare);
  ASSERT_EQ(run({geo.string(), "-2"}), 0) << err_.str();
  EXPECT_TRUE(fs::exists(dir_ / "plate.msh"));
  std::ifstream in(dir_ / "plate.msh");
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "$MeshFormat");
}

TEST_F(Cli, PrintfGoesToStdoutAndLogToStderr) {
  fs::path geo = write("p.geo", kSquare);
  ASSERT_EQ(run({geo.string(), "-2", "-o", (dir_ / "o.msh").string()}), 0) << err_.str();
  EXPECT_EQ(out_.str(), "square ready\n");
  EXPECT_NE(err_.str().find("Info"), std::string::npos);
}

TEST_F(Cli, VerbosityZeroIsSilent) {
  fs::path geo = write("p.geo", kSquare);
  ASSERT_EQ(run({geo.string(), "-2", "-v", "0", "-o", (dir_ / "o.msh").string()}), 0);
  EXPECT_EQ(err_.str(), "");
}

TEST_F(Cli, SyntaxErrorPointsAtLineAndColumnAndWritesNothing) {
  fs::path geo = write("bad.geo", "a = 1;\nb = (a + ;\n");
  EXPECT_EQ(run({geo.string(), "-2"}), 1);
  const std::string err = err_.str();
  EXPECT_NE(err.find("bad.geo:2:10: error:"), std::string::npos) << err;
  EXPECT_NE(err.find("b = (a + ;"), std::string::npos) << err;
  EXPECT_NE(err.find("         ^"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir_ / "bad.msh"));
}

TEST_F(Cli, UnknownFlagIsAnError) {
  EXPECT_EQ(run({"x.geo", "-notaflag"}), 1);
  EXPECT_NE(err_.str().find("-notaflag"), std::string::npos);
}

TEST_F(Cli, MissingFileIsAnError) {
  EXPECT_EQ(run({(dir_ / "absent.geo").string(), "-2"}), 1);
  EXPECT_NE(err_.str().find("absent.geo"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "absent.msh"));
}

TEST_F(Cli, NoFileIsAnError) {
  EXPECT_EQ(run({"-2"}), 1);
}

TEST_F(Cli, VersionAndHelp) {
  EXPECT_EQ(run({"-version"}), 0);
  EXPECT_EQ(out_.str(), "0.1.0\n");
  EXPECT_EQ(run({"-help"}), 0);
  EXPECT_NE(out_.str().find("Usage: geomesh"), std::string::npos);
}

TEST_F(Cli, SetNumberOverridesDefineConstant) {
  fs::path geo = write("p.geo", "DefineConstant[ n = 3 ];\nPrintf(\"n=%g\", n);\n");
  ASSERT_EQ(run({geo.string(), "-0", "-setnumber", "n", "7"}), 0) << err_.str();
  EXPECT_EQ(out_.str(), "n=7\n");
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(Cli, ScriptOptionsOverrideCommandLineFlags) {
  // Flags set options before the script runs, so what the script sets wins, as in Gmsh.
  fs::path plain = write("plain.geo", kSquare);
  fs::path fixed = write("fixed.geo", std::string(kSquare) +
                                          "Mesh.MeshSizeFactor = 1;\nMesh.Algorithm = 5;\n"
                                          "Printf(\"factor %g algorithm %g\", "
                                          "Mesh.MeshSizeFactor, Mesh.Algorithm);\n");
  ASSERT_EQ(run({fixed.string(), "-2", "-clscale", "0.5", "-algo", "front2d", "-o",
                 (dir_ / "fixed.msh").string()}),
            0)
      << err_.str();
  EXPECT_EQ(out_.str(), "square ready\nfactor 1 algorithm 5\n");
  ASSERT_EQ(run({plain.string(), "-2", "-algo", "del2d", "-o", (dir_ / "plain.msh").string()}), 0)
      << err_.str();
  EXPECT_EQ(slurp(dir_ / "fixed.msh"), slurp(dir_ / "plain.msh"));
  ASSERT_EQ(run({plain.string(), "-2", "-clscale", "0.5", "-o", (dir_ / "fine.msh").string()}), 0)
      << err_.str();
  EXPECT_GT(slurp(dir_ / "fine.msh").size(), 2 * slurp(dir_ / "plain.msh").size());
}

TEST_F(Cli, SetNumberAndSetStringAlsoSetOptions) {
  fs::path geo = write("p.geo",
                       "Printf(\"%g\", Mesh.Algorithm);\n"
                       "Printf(StrCat(\"name \", General.DefaultFileName));\n");
  ASSERT_EQ(run({geo.string(), "-0", "-setnumber", "Mesh.Algorithm", "5", "-setstring",
                 "General.DefaultFileName", "plate.geo"}),
            0)
      << err_.str();
  EXPECT_EQ(out_.str(), "5\nname plate.geo\n");
}

TEST_F(Cli, MeshFailureWritesNoFile) {
  // A loop whose curves do not close is refused with the line of the loop.
  fs::path geo =
      write("open.geo", R"(Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3};
Curve Loop(1) = {1, 2};
Plane Surface(1) = {1};
)");
  EXPECT_EQ(run({geo.string(), "-2"}), 1);
  EXPECT_NE(err_.str().find("open.geo:3:"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "open.msh"));
}

// The real executable: exit statuses as the shell sees them.
TEST_F(Cli, ExecutableExitStatus) {
  fs::path good = write("good.geo", kSquare);
  fs::path bad = write("bad.geo", "Point(1) = {0, 0, 0\n");
  const std::string exe = GEOMESH_BINARY;
  const std::string quiet = " -v 0 > /dev/null 2>&1";
  EXPECT_EQ(std::system((exe + " " + good.string() + " -2" + quiet).c_str()), 0);
  EXPECT_TRUE(fs::exists(dir_ / "good.msh"));
  int status = std::system((exe + " " + bad.string() + " -2" + quiet).c_str());
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_FALSE(fs::exists(dir_ / "bad.msh"));
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST_F(Cli, CheckAcceptsAWrittenMesh) {
  fs::path geo = write("sq.geo", kSquare);
  ASSERT_EQ(run({geo.string(), "-2", "-save_all", "-o", (dir_ / "sq.msh").string()}), 0);
  EXPECT_EQ(run({(dir_ / "sq.msh").string(), "-check"}), 0) << err_.str();
  EXPECT_NE(err_.str().find("no problem"), std::string::npos) << err_.str();
}

TEST_F(Cli, PartitionedMeshesPassTheCheckAndSplitIntoFiles) {
  fs::path geo = write("sq.geo", kSquare);
  const std::string whole = (dir_ / "sq.msh").string();
  ASSERT_EQ(run({geo.string(), "-2", "-part", "3", "-save_all", "-o", whole}), 0) << err_.str();
  EXPECT_NE(err_.str().find("Done partitioning mesh into 3 parts"), std::string::npos);
  EXPECT_EQ(run({whole, "-check"}), 0) << err_.str();
  // A mesh file partitioned anew, one file per partition.
  ASSERT_EQ(run({whole, "-part", "2", "-part_split", "-o", (dir_ / "two.msh").string()}), 0)
      << err_.str();
  EXPECT_TRUE(fs::exists(dir_ / "two_1.msh"));
  EXPECT_TRUE(fs::exists(dir_ / "two_2.msh"));
  EXPECT_FALSE(fs::exists(dir_ / "two.msh"));
}

TEST_F(Cli, MorePartitionsThanElementsFailsWithBothNumbersAndNoFile) {
  fs::path geo = write("sq.geo", kSquare);
  const fs::path out = dir_ / "many.msh";
  EXPECT_EQ(run({geo.string(), "-2", "-part", "5000", "-o", out.string()}), 1);
  EXPECT_NE(err_.str().find("cannot make 5000 partitions of "), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, CheckReportsANonConformingMesh) {
  // Edge 1-2 is shared by three triangles.
  fs::path msh = write("bad.msh", R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
0 0 1 0
1 0 0 0 1 1 0 0 0
$EndEntities
$Nodes
1 4 1 4
2 1 0 4
1
2
3
4
0 0 0
1 0 0
0 1 0
1 -1 0
$EndNodes
$Elements
1 3 1 3
2 1 2 3
1 1 2 3
2 2 1 4
3 1 2 4
$EndElements
)");
  EXPECT_EQ(run({msh.string(), "-check"}), 1);
  EXPECT_NE(err_.str().find("surface 1"), std::string::npos) << err_.str();
}

// The unit square as two second-order triangles bounded by four second-order lines; `node2`
// is where the node of the edge from (0, 0) to (1, 0) goes (its midpoint when straight).
std::string squareOfTriangle6(const std::string& node2) {
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
         "$Entities\n0 4 1 0\n1 0 0 0 1 0 0 0 0\n2 1 0 0 1 1 0 0 0\n3 0 1 0 1 1 0 0 0\n"
         "4 0 0 0 0 1 0 0 0\n1 0 0 0 1 1 0 0 4 1 2 3 4\n$EndEntities\n"
         "$Nodes\n1 9 1 9\n2 1 0 9\n1\n2\n3\n4\n5\n6\n7\n8\n9\n0 0 0\n" +
         node2 +
         "\n1 0 0\n0 0.5 0\n0.5 0.5 0\n1 0.5 0\n0 1 0\n0.5 1 0\n1 1 0\n$EndNodes\n"
         "$Elements\n5 6 1 6\n1 1 8 1\n1 1 3 2\n1 2 8 1\n2 3 9 6\n1 3 8 1\n3 9 7 8\n"
         "1 4 8 1\n4 7 1 4\n2 1 9 2\n5 1 3 9 2 6 5\n6 1 9 7 5 8 4\n$EndElements\n";
}

TEST_F(Cli, CheckReportsTheScaledJacobianOfACurvedMesh) {
  fs::path msh = write("p2.msh", squareOfTriangle6("0.5 -0.1 0"));
  EXPECT_EQ(run({msh.string(), "-check"}), 0) << err_.str();
  EXPECT_NE(err_.str().find("curved elements: scaled Jacobian min"), std::string::npos)
      << err_.str();
  EXPECT_NE(err_.str().find(", 0 invalid"), std::string::npos) << err_.str();
  EXPECT_NE(err_.str().find("no problem"), std::string::npos) << err_.str();
  // Area of the square plus the parabolic bulge below its bottom edge: (2/3) 1 0.1.
  EXPECT_NE(err_.str().find("area 1.06667"), std::string::npos) << err_.str();
}

TEST_F(Cli, CheckFailsOnAnInvalidCurvedElement) {
  // The edge node pulled across the opposite vertex (1, 1): its triangle folds, and its
  // boundary line runs backwards.
  fs::path msh = write("p2bad.msh", squareOfTriangle6("1.1 1.3 0"));
  EXPECT_EQ(run({msh.string(), "-check"}), 1);
  EXPECT_NE(err_.str().find("2 invalid curved element(s)"), std::string::npos) << err_.str();
  EXPECT_EQ(err_.str().find("no problem"), std::string::npos) << err_.str();
}

TEST_F(Cli, FirstOrderMeshesPrintNoCurvedLine) {
  fs::path geo = write("sq.geo", kSquare);
  ASSERT_EQ(run({geo.string(), "-2", "-o", (dir_ / "sq.msh").string()}), 0);
  EXPECT_EQ(err_.str().find("scaled Jacobian"), std::string::npos) << err_.str();
}

TEST_F(Cli, MalformedMeshFileIsAnErrorWithItsLine) {
  fs::path msh = write("broken.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2\n");
  EXPECT_EQ(run({msh.string(), "-check"}), 1);
  EXPECT_NE(err_.str().find("broken.msh:"), std::string::npos) << err_.str();
}

TEST_F(Cli, ConvertsMsh41ToMsh22) {
  fs::path geo = write("sq.geo", kSquare);
  ASSERT_EQ(run({geo.string(), "-2", "-o", (dir_ / "sq.msh").string()}), 0);
  ASSERT_EQ(
      run({(dir_ / "sq.msh").string(), "-o", (dir_ / "sq22.msh").string(), "-format", "msh22"}), 0)
      << err_.str();
  std::ifstream in(dir_ / "sq22.msh");
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  EXPECT_EQ(line, "2.2 0 8");
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

// The line after `section` in a mesh file (its counts).
std::string sectionHeader(const fs::path& file, const std::string& section) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line == section && std::getline(in, line)) return line;
  return "";
}

TEST_F(Cli, DimensionZeroWritesTheUnrolledGeometryWhichMeshesTheSame) {
  fs::path geo = write("loop.geo", R"(n = 5;
For i In {1:n}
  Point(i) = {Cos(2 * Pi * i / n), Sin(2 * Pi * i / n), 0, 0.2};
EndFor
For i In {1:n}
  Line(i) = {i, i % n + 1};
EndFor
Curve Loop(1) = {1:n};
Plane Surface(1) = {1};
Physical Surface("pentagon") = {1};
)");
  ASSERT_EQ(run({geo.string(), "-0"}), 0) << err_.str();
  const fs::path unrolled = dir_ / "loop.geo_unrolled";
  ASSERT_TRUE(fs::exists(unrolled));
  EXPECT_FALSE(fs::exists(dir_ / "loop.msh"));
  std::ifstream in(unrolled);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("Line(5) = {5, 1};"), std::string::npos) << text.str();
  EXPECT_EQ(text.str().find("For"), std::string::npos) << text.str();

  ASSERT_EQ(run({geo.string(), "-2", "-o", (dir_ / "a.msh").string()}), 0);
  fs::path copy = dir_ / "copy.geo";
  fs::copy_file(unrolled, copy);
  ASSERT_EQ(run({copy.string(), "-2", "-o", (dir_ / "b.msh").string()}), 0) << err_.str();
  // Coordinates are written with 16 significant digits (as the reference writes them), so
  // the two meshes agree in counts, not to the last bit.
  EXPECT_EQ(sectionHeader(dir_ / "a.msh", "$Nodes"), sectionHeader(dir_ / "b.msh", "$Nodes"));
  EXPECT_EQ(sectionHeader(dir_ / "a.msh", "$Elements"), sectionHeader(dir_ / "b.msh", "$Elements"));
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

#if defined(__SANITIZE_ADDRESS__)
#define GEOMESH_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GEOMESH_UNDER_ASAN 1
#endif
#endif

// Memory runs out (the address space is limited to 400 MB): the run ends with an error, not a
// crash, and writes nothing.
TEST_F(Cli, MemoryExhaustionEndsWithAnError) {
#ifdef GEOMESH_UNDER_ASAN
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit allows";
#else
  fs::path geo = write("hungry.geo", R"(a[] = {};
For i In {1:200}
  For j In {1:1000000}
    a[] += j;
  EndFor
EndFor
)");
  const std::string cmd = "ulimit -v 400000; " + std::string(GEOMESH_BINARY) + " " + geo.string() +
                          " -2 > " + (dir_ / "log.txt").string() + " 2>&1";
  const int status = std::system(("sh -c '" + cmd + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  std::ifstream in(dir_ / "log.txt");
  std::stringstream log;
  log << in.rdbuf();
  EXPECT_NE(log.str().find("out of memory"), std::string::npos) << log.str();
  EXPECT_FALSE(fs::exists(dir_ / "hungry.msh"));
#endif
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

const char* kCrossingCurves = R"(Point(1) = {0, 0, 0, 0.1}; Point(2) = {3, 0, 0, 0.1};
Point(3) = {0, 1, 0, 0.1}; Point(4) = {1, 2, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
)";

TEST_F(Cli, MeshingFailureNamesTheEntityAndWritesNothing) {
  fs::path geo = write("bow.geo", kCrossingCurves);
  EXPECT_EQ(run({geo.string(), "-2"}), 1);
  EXPECT_NE(err_.str().find("surface 1"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "bow.msh"));
  EXPECT_FALSE(fs::exists(dir_ / "bow.msh.partial"));
}

TEST_F(Cli, KeepPartialWritesWhatWasMeshed) {
  fs::path geo = write("bow.geo", kCrossingCurves);
  EXPECT_EQ(run({geo.string(), "-2", "-keep_partial"}), 1);
  ASSERT_TRUE(fs::exists(dir_ / "bow.msh")) << err_.str();
  // The curves were meshed before the surface failed.
  EXPECT_NE(sectionHeader(dir_ / "bow.msh", "$Elements"), "");
  EXPECT_NE(err_.str().find("-keep_partial"), std::string::npos) << err_.str();
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST_F(Cli, AnUnsupportedOutputExtensionIsRefusedBeforeMeshing) {
  fs::path geo = write("sq.geo", kSquare);
  EXPECT_EQ(run({geo.string(), "-2", "-o", (dir_ / "sq.wrl").string()}), 1);
  EXPECT_NE(err_.str().find("'.wrl' format is not supported"), std::string::npos) << err_.str();
  EXPECT_EQ(err_.str().find("Meshing 1D"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "sq.wrl"));
  // An explicit format writes MSH whatever the name.
  EXPECT_EQ(run({geo.string(), "-2", "-format", "msh41", "-o", (dir_ / "sq.mesh41").string()}), 0);
  EXPECT_TRUE(fs::exists(dir_ / "sq.mesh41"));
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST_F(Cli, SystemCallsAreRefusedUnlessAllowed) {
  const fs::path marker = dir_ / "ran.txt";
  fs::path geo =
      write("sys.geo", "SystemCall \"touch " + marker.string() + "\";\nPrintf(\"on\");\n");
  ASSERT_EQ(run({geo.string(), "-0"}), 0) << err_.str();
  EXPECT_FALSE(fs::exists(marker));
  EXPECT_EQ(out_.str(), "on\n");
  EXPECT_NE(err_.str().find("sys.geo:1:1: warning: 'SystemCall' refused"), std::string::npos)
      << err_.str();
  ASSERT_EQ(run({geo.string(), "-0", "-allow_system_calls"}), 0) << err_.str();
  EXPECT_TRUE(fs::exists(marker));
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

// A CAD kernel and a CAD file that geomesh does not read: every statement is ignored.
const char* kForeignCadOnly = R"(SetFactory("Parasolid");
Merge "wing.x_t";
Smoother Surface{1} = 3;
)";

TEST_F(Cli, MeshingAModelThatIgnoredStatementsLeftEmptyIsAnError) {
  fs::path geo = write("cad.geo", kForeignCadOnly);
  EXPECT_EQ(run({geo.string(), "-3"}), 1);
  const std::string err = err_.str();
  EXPECT_NE(err.find(geo.string() + ":1:1: error: nothing to mesh: 3 statements were ignored as "
                                    "not supported yet (the first here) and the model has no "
                                    "point, curve, surface or volume\n"
                                    "SetFactory(\"Parasolid\");\n^"),
            std::string::npos)
      << err;
  EXPECT_EQ(err.find("Meshing 1D"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir_ / "cad.msh"));
  EXPECT_FALSE(fs::exists(dir_ / "cad.msh.partial"));
  // Evaluating it alone is no error: nothing was asked to be meshed.
  EXPECT_EQ(run({geo.string()}), 0) << err_.str();
}

TEST_F(Cli, IgnoredStatementsBesideGeometryStillMesh) {
  fs::path geo = write("mixed.geo", std::string(kSquare) + "Smoother Surface{1} = 3;\n");
  EXPECT_EQ(run({geo.string(), "-2"}), 0) << err_.str();
  EXPECT_NE(err_.str().find("'Smoother Surface' is not supported yet"), std::string::npos)
      << err_.str();
  EXPECT_TRUE(fs::exists(dir_ / "mixed.msh"));
}

TEST_F(Cli, FormatErrorsListTheTablesNames) {
  fs::path geo = write("sq.geo", kSquare);
  EXPECT_EQ(run({geo.string(), "-2", "-format", "nope"}), 1);
  EXPECT_NE(err_.str().find("unsupported output format 'nope' (supported: msh41, msh4, msh, "
                            "msh22, msh2"),
            std::string::npos)
      << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "sq.msh"));
  EXPECT_EQ(run({"-help"}), 0);
  EXPECT_NE(out_.str().find("-format FORMAT         output format: msh41 (msh4, msh), "
                            "msh22 (msh2)"),
            std::string::npos)
      << out_.str();
}

TEST_F(Cli, MeshFormatOptionAndVersionChooseTheRow) {
  fs::path geo = write("sq.geo", std::string(kSquare) + "Mesh.MshFileVersion = 2.2;\n");
  ASSERT_EQ(run({geo.string(), "-2"}), 0) << err_.str();
  EXPECT_EQ(slurp(dir_ / "sq.msh").rfind("$MeshFormat\n2.2 0 8\n", 0), 0u);
  fs::path coded = write("coded.geo", std::string(kSquare) + "Mesh.Format = 1;\n");
  ASSERT_EQ(run({coded.string(), "-2", "-o", (dir_ / "coded.out").string()}), 0) << err_.str();
  EXPECT_EQ(slurp(dir_ / "coded.out").rfind("$MeshFormat\n4.1 0 8\n", 0), 0u);
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST_F(Cli, WritesVtkByExtensionOrByName) {
  fs::path geo = write("x.geo", kSquare);
  ASSERT_EQ(run({geo.string(), "-2", "-o", (dir_ / "x.vtk").string()}), 0) << err_.str();
  ASSERT_EQ(run({geo.string(), "-2", "-o", (dir_ / "x.msh").string()}), 0) << err_.str();
  const std::string vtk = slurp(dir_ / "x.vtk");
  EXPECT_EQ(vtk.rfind("# vtk DataFile Version 2.0\n", 0), 0u) << vtk;
  EXPECT_NE(vtk.find("\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS "), std::string::npos);
  // As many points and cells as the MSH file has nodes and elements.
  std::istringstream nodes(sectionHeader(dir_ / "x.msh", "$Nodes"));
  std::istringstream elements(sectionHeader(dir_ / "x.msh", "$Elements"));
  std::size_t blocks = 0, nodeCount = 0, elementCount = 0;
  nodes >> blocks >> nodeCount;
  elements >> blocks >> elementCount;
  EXPECT_NE(vtk.find("\nPOINTS " + std::to_string(nodeCount) + " double\n"), std::string::npos);
  EXPECT_NE(vtk.find("\nCELL_TYPES " + std::to_string(elementCount) + "\n"), std::string::npos);
  EXPECT_NE(vtk.find("\nCELL_DATA " + std::to_string(elementCount) + "\n"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "x.vtk.partial"));
  ASSERT_EQ(run({geo.string(), "-2", "-format", "vtk", "-o", (dir_ / "named.out").string()}), 0);
  EXPECT_EQ(slurp(dir_ / "named.out"), vtk);
}

}  // namespace
}  // namespace geomesh
