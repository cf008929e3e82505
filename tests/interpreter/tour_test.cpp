// The tour.geo script prints what the reference prints; -setnumber overrides its constants.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Tour, PrintsWhatTheReferencePrints) {
  const std::string dir = std::string(GEOMESH_SOURCE_DIR) + "/tests/interpreter/scripts/";
  ScriptRun run;
  runScriptFile(run.session, dir + "tour.geo");
  EXPECT_EQ(run.out.str(), readText(dir + "tour.expected"));
  EXPECT_TRUE(run.log.warnings.empty());
  run.session.synchronize();
  EXPECT_EQ(run.session.model().surfaces().size(), 1u);
  EXPECT_EQ(run.session.model().physicalGroups().size(), 2u);
}

TEST(Tour, CommandLineOverridesDefineConstant) {
  const std::string dir = std::string(GEOMESH_SOURCE_DIR) + "/tests/interpreter/scripts/";
  ScriptRun run;
  run.session.numberOverrides()["n"] = 2;
  runScriptFile(run.session, dir + "tour.geo");
  EXPECT_EQ(run.out.str().substr(0, 9), "lc = 0.5\n");
}

}  // namespace
}  // namespace geomesh::testing
