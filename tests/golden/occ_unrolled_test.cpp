// -0 of an OpenCASCADE model: the unrolled script merges an XAO file of the shapes, and running
// it gives the same model (tags, physical groups, mesh constraints) and the same mesh.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/mesh_summary.h"
#include "app/run.h"
#include "io/msh_reader.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh {
namespace {

// A block with a bore, a boss and a free point, with tags that are not 1..n, physical groups,
// sizes at points and a transfinite curve.
constexpr const char* kScript = R"(SetFactory("OpenCASCADE");
Box(5) = {0, 0, 0, 4, 2, 1};
Cylinder(7) = {1, 1, -0.5, 0, 0, 2, 0.4};
Cylinder(8) = {3, 1, 1, 0, 0, 0.5, 0.5};
u() = BooleanUnion{ Volume{5}; Delete; }{ Volume{8}; Delete; };
d() = BooleanDifference{ Volume{u(0)}; Delete; }{ Volume{7}; Delete; };
Point(100) = {7, 7, 7};
Physical Volume("part", 4) = {d(0)};
Physical Surface(9) = {1, 2};
MeshSize{1, 2} = 0.15;
Transfinite Curve{3} = 12;
Mesh.MeshSizeMax = 0.4;
v() = Volume{:}; s() = Surface{:}; c() = Curve{:}; p() = Point{:};
)";

constexpr const char* kReport =
    R"(Printf("model: %g %g %g %g; last tags %g %g %g %g", #v(), #s(), #c(), #p(), v(#v()-1),
       s(#s()-1), c(#c()-1), p(#p()-1));
)";

std::string run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  EXPECT_EQ(runGeomesh(args, out, err), 0) << err.str();
  return out.str();
}

std::string reportLine(const std::string& out) {
  const std::size_t at = out.find("model: ");
  return at == std::string::npos ? "" : out.substr(at, out.find('\n', at) - at);
}

MeshSummary summary(const fs::path& msh) {
  Model model;
  Mesh mesh;
  readMshFile(msh.string(), model, mesh);
  return summarizeMesh(model, mesh);
}

TEST(OccUnrolled, RerunningTheUnrolledScriptGivesTheSameModelAndMesh) {
  const fs::path dir = scratch::path("occ-unrolled");
  fs::create_directories(dir);
  const fs::path script = dir / "part.geo";
  std::ofstream(script) << kScript << kReport;
  const std::string original = reportLine(run({script.string(), "-0"}));
  const fs::path unrolled = dir / "part.geo_unrolled";
  ASSERT_TRUE(fs::exists(dir / "part.geo_unrolled.xao"));
  std::ifstream in(unrolled);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "SetFactory(\"OpenCASCADE\");");
  std::getline(in, first);
  EXPECT_EQ(first, "Merge \"part.geo_unrolled.xao\";");

  // The unrolled script, with the same report, run in place of the original.
  const fs::path again = dir / "again.geo";
  {
    std::ifstream text(unrolled);
    std::ostringstream copy;
    copy << text.rdbuf();
    std::ofstream(again) << copy.str() << "Mesh.MeshSizeMax = 0.4;\n"
                         << "v() = Volume{:}; s() = Surface{:}; c() = Curve{:}; p() = Point{:};\n"
                         << kReport;
  }
  fs::copy_file(dir / "part.geo_unrolled.xao", dir / "again.geo_unrolled.xao");
  EXPECT_FALSE(original.empty());
  EXPECT_EQ(reportLine(run({again.string(), "-0", "-o", (dir / "again2.geo_unrolled").string()})),
            original);

  run({script.string(), "-3", "-o", (dir / "a.msh").string()});
  run({again.string(), "-3", "-o", (dir / "b.msh").string()});
  const MeshSummary a = summary(dir / "a.msh"), b = summary(dir / "b.msh");
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.elements, b.elements);
  ASSERT_EQ(a.physicalGroups.size(), b.physicalGroups.size());
  EXPECT_NEAR(a.volume, b.volume, 1e-12);
  fs::remove_all(dir);
}

// Built-in entities beside OpenCASCADE ones stay the built-in kernel's, with their tags.
TEST(OccUnrolled, BuiltInEntitiesFollowTheMergedShapes) {
  const fs::path dir = scratch::path("occ-unrolled-mixed");
  fs::create_directories(dir);
  const fs::path script = dir / "mixed.geo";
  std::ofstream(script) << "SetFactory(\"OpenCASCADE\");\nBox(3) = {0, 0, 0, 1, 1, 1};\n"
                           "SetFactory(\"Built-in\");\nPoint(50) = {9, 9, 9};\n"
                           "Physical Volume(2) = {3};\n";
  run({script.string(), "-0"});
  std::ifstream in(dir / "mixed.geo_unrolled");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_GE(lines.size(), 5u);
  EXPECT_EQ(lines[0], "SetFactory(\"OpenCASCADE\");");
  EXPECT_EQ(lines[1], "Merge \"mixed.geo_unrolled.xao\";");
  EXPECT_EQ(lines[2], "SetFactory(\"Built-in\");");
  EXPECT_EQ(lines.back(), "Physical Volume(2) = {3};");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace geomesh
