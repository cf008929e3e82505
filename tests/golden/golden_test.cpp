// Golden script tests: each tests/golden/scripts/NAME.geo (each tutorials/NAME.geo with a
// tests/golden/tutorials/NAME.expected, and each malformed script of tests/golden/bad_input)
// runs through the geomesh command with the arguments of
// NAME.expected; the mesh file it writes is read back and summarized, and the summary is
// compared with NAME.expected, with tolerances.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "app/mesh_summary.h"
#include "app/run.h"
#include "golden_expectation.h"
#include "io/msh_reader.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh::golden {
namespace {

struct GoldenFiles {
  std::string name;
  fs::path script;
  fs::path expected;
};

void PrintTo(const GoldenFiles& f, std::ostream* os) { *os << f.name; }

std::vector<GoldenFiles> goldenCases() {
  const fs::path source(GEOMESH_SOURCE_DIR);
  const fs::path golden = source / "tests" / "golden";
  std::vector<GoldenFiles> cases;
  auto collect = [&](const fs::path& expectedDir, const fs::path& scriptDir, const char* prefix) {
    for (const auto& entry : fs::directory_iterator(expectedDir)) {
      if (entry.path().extension() != ".expected") continue;
      const std::string stem = entry.path().stem().string();
      cases.push_back({prefix + stem, scriptDir / (stem + ".geo"), entry.path()});
    }
  };
  collect(golden / "scripts", golden / "scripts", "");
  collect(golden / "tutorials", source / "tutorials", "tutorial_");
  collect(golden / "bad_input", golden / "bad_input", "bad_");
  std::sort(cases.begin(), cases.end(),
            [](const GoldenFiles& a, const GoldenFiles& b) { return a.name < b.name; });
  return cases;
}

// The figure a key of a .expected file names, from a summary.
bool figure(const MeshSummary& s, const std::string& key, double& value) {
  if (key == "nodes") {
    value = static_cast<double>(s.nodes);
  } else if (key == "length") {
    value = s.length;
  } else if (key == "area") {
    value = s.area;
  } else if (key == "volume") {
    value = s.volume;
  } else if (key == "quality.min") {
    value = s.minQuality;
  } else if (key == "quality.mean") {
    value = s.meanQuality;
  } else if (key == "jacobian.min") {
    value = s.minScaledJacobian;
  } else if (key == "jacobian.invalid") {
    value = static_cast<double>(s.invalidElements);
  } else if (key == "quads.irregular") {
    value = static_cast<double>(s.irregularVertices);
  } else if (key == "hexahedra.share") {
    value = s.volume > 0 ? s.hexahedraVolume / s.volume : 0;
  } else if (key == "groups") {
    value = static_cast<double>(s.physicalGroups.size());
  } else if (key == "elements.total") {
    value = 0;
    for (const auto& [type, n] : s.elements) value += static_cast<double>(n);
  } else if (key.rfind("elements.", 0) == 0) {
    value = 0;
    for (const auto& [type, n] : s.elements)
      if (key.substr(9) == elementName(type)) value = static_cast<double>(n);
  } else {
    return false;
  }
  return true;
}

void expectStdout(const GoldenCase& c, const std::string& out) {
  std::istringstream in(out);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  std::size_t next = 0;
  for (const std::string& want : c.stdoutLines) {
    auto it = std::find(lines.begin() + static_cast<std::ptrdiff_t>(next), lines.end(), want);
    ASSERT_NE(it, lines.end()) << "missing stdout line (in order): " << want << "\nstdout:\n" << out;
    next = static_cast<std::size_t>(it - lines.begin()) + 1;
  }
}

void expectSummary(const GoldenCase& c, const fs::path& mshPath) {
  ASSERT_TRUE(fs::exists(mshPath)) << "no mesh written";
  Model model;
  Mesh mesh;
  readMshFile(mshPath.string(), model, mesh);
  MeshSummary s = summarizeMesh(model, mesh);
  for (const Expectation& e : c.figures) {
    double value = 0;
    ASSERT_TRUE(figure(s, e.key, value)) << "unknown key '" << e.key << "' at line " << e.line;
    std::string why;
    EXPECT_TRUE(satisfies(e, value, why)) << e.key << " (line " << e.line << "): " << why;
  }
  for (const std::string& want : c.physicals) {
    bool found = false;
    for (const MeshSummary::Group& g : s.physicalGroups) {
      std::ostringstream os;
      os << g.dim << ' ' << g.tag;
      if (!g.name.empty()) os << ' ' << g.name;
      found = found || os.str() == want;
    }
    EXPECT_TRUE(found) << "missing physical group '" << want << "'";
  }
}

class GoldenScript : public testing::TestWithParam<GoldenFiles> {};

TEST_P(GoldenScript, MatchesExpectedSummary) {
  const std::string& name = GetParam().name;
  const GoldenCase c = readExpectations(GetParam().expected.string());
  const fs::path msh = scratch::path("golden-" + name + ".msh");
  fs::remove(msh);
  std::vector<std::string> args = c.args;
  args.push_back(GetParam().script.string());
  args.insert(args.end(), {"-o", msh.string()});
  std::ostringstream out, err;
  const int status = runGeomesh(args, out, err);
  ASSERT_EQ(status, c.exitStatus) << "stderr:\n" << err.str();
  expectStdout(c, out.str());
  for (const std::string& fragment : c.stderrFragments)
    EXPECT_NE(err.str().find(fragment), std::string::npos)
        << "stderr lacks '" << fragment << "':\n" << err.str();
  if (c.exitStatus != 0) {
    EXPECT_FALSE(fs::exists(msh)) << "a failed run left a mesh file behind";
  } else if (!c.figures.empty() || !c.physicals.empty()) {
    expectSummary(c, msh);
  }
  fs::remove(msh);
  fs::remove(msh.string() + ".xao");  // -0 of an OpenCASCADE model writes its shapes beside
}

std::string caseName(const testing::TestParamInfo<GoldenFiles>& info) {
  std::string n = info.param.name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Scripts, GoldenScript, testing::ValuesIn(goldenCases()), caseName);

}  // namespace
}  // namespace geomesh::golden
