// Tests of Include: relative paths, missing files, cycles, include chains in errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "script_runner.h"
#include "tests/scratch.h"

namespace geomesh::testing {
namespace {

namespace fs = std::filesystem;

// A fresh directory of script files for one test.
class IncludeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch::path(
        "include-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sub");
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs main.geo; returns its output or its diagnostic.
  std::string runMain() {
    ScriptRun run;
    try {
      runScriptFile(run.session, path("main.geo"));
    } catch (const ScriptError& error) {
      return error.what();
    }
    return run.out.str();
  }

  fs::path dir_;
};

TEST_F(IncludeTest, PathsAreRelativeToTheIncludingFile) {
  write("main.geo", "Include \"sub/part.geo\";\nPrintf(\"%g %g\", inc, leaf);\n");
  write("sub/part.geo", "inc = 42;\nInclude \"leaf.geo\";\n");
  write("sub/leaf.geo", "leaf = 1;\n");
  EXPECT_EQ(runMain(), "42 1\n");
}

TEST_F(IncludeTest, MissingFileIsAnErrorAtTheInclude) {
  write("main.geo", "a = 1;\nInclude \"nope.geo\";\n");
  std::string error = runMain();
  EXPECT_EQ(error.substr(0, error.find('\n')),
            path("main.geo") + ":2:9: error: cannot open include file '" + path("nope.geo") + "'");
}

TEST_F(IncludeTest, CyclesAreErrors) {
  write("main.geo", "Include \"a.geo\";\n");
  write("a.geo", "Include \"main.geo\";\n");
  std::string error = runMain();
  EXPECT_NE(error.find("a.geo:1:9: error: include cycle"), std::string::npos) << error;
  EXPECT_NE(error.find("  included from " + path("main.geo") + ":1:1"), std::string::npos) << error;
}

TEST_F(IncludeTest, ErrorsInIncludedFilesShowTheIncludeChain) {
  write("main.geo", "x = 1;\nInclude \"sub/part.geo\";\n");
  write("sub/part.geo", "\nInclude \"leaf.geo\";\n");
  write("sub/leaf.geo", "y = zz;\n");
  EXPECT_EQ(runMain(), path("sub/leaf.geo") + ":1:5: error: undefined variable 'zz'\n"
                       "y = zz;\n"
                       "    ^\n"
                       "  included from " + path("sub/part.geo") + ":2:1\n"
                       "  included from " + path("main.geo") + ":2:1");
}

TEST_F(IncludeTest, PrintfRedirectsToFilesBesideTheScript) {
  write("main.geo", "Printf(\"one\") > \"out.txt\";\nPrintf(\"two %g\", 2) >> \"out.txt\";\n");
  EXPECT_EQ(runMain(), "");
  std::ifstream in(dir_ / "out.txt");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "one\ntwo 2\n");
}

TEST_F(IncludeTest, MissingMainFile) {
  ScriptRun run;
  EXPECT_THROW(runScriptFile(run.session, path("absent.geo")), ScriptError);
}

}  // namespace
}  // namespace geomesh::testing
