// `geomesh view FILE` and -view: the HTML page written beside the mesh (or at -o), a clear
// error and no page for a missing, unreadable or non-mesh input.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app/command_line.h"
#include "tests/app/command_fixture.h"

namespace geomesh {
namespace {

const char* kSquare = R"(
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5};
Point(3) = {1, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("square", 3) = {1};
)";

class ViewCommand : public CommandTest {
 protected:
  ViewCommand() : CommandTest("view-") {}
  void SetUp() override {
    CommandTest::SetUp();
    // No browser is opened during the tests.
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
  }
  std::string read(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  bool anyPage() {
    for (const auto& entry : std::filesystem::directory_iterator(dir_))
      if (entry.path().extension() == ".html" || entry.path().extension() == ".partial")
        return true;
    return false;
  }
};

TEST_F(ViewCommand, ParsesTheCommandAndTheFlag) {
  const CommandLine view = parseCommandLine({"view", "mesh.msh", "-o", "page.html"});
  EXPECT_TRUE(view.viewCommand);
  EXPECT_TRUE(view.view);
  EXPECT_EQ(view.files, std::vector<std::string>{"mesh.msh"});
  EXPECT_EQ(view.output, "page.html");
  const CommandLine flag = parseCommandLine({"t1.geo", "-2", "-view"});
  EXPECT_FALSE(flag.viewCommand);
  EXPECT_TRUE(flag.view);
}

TEST_F(ViewCommand, WritesThePageBesideTheMesh) {
  const auto script = write("square.geo", kSquare);
  ASSERT_EQ(run({script.string(), "-2"}), 0) << err_.str();
  ASSERT_EQ(run({"view", (dir_ / "square.msh").string()}), 0) << err_.str();
  const std::string page = read(dir_ / "square.html");
  EXPECT_NE(page.find(R"("name":"square","dim":2,"tag":3,"physical":true)"), std::string::npos);
  EXPECT_NE(err_.str().find("Open '"), std::string::npos) << err_.str();
}

TEST_F(ViewCommand, OutputNamesThePage) {
  const auto script = write("square.geo", kSquare);
  ASSERT_EQ(run({script.string(), "-2"}), 0) << err_.str();
  ASSERT_EQ(run({"view", (dir_ / "square.msh").string(), "-o", (dir_ / "p.html").string()}), 0)
      << err_.str();
  EXPECT_TRUE(std::filesystem::exists(dir_ / "p.html"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "square.html"));
}

TEST_F(ViewCommand, ViewAfterMeshingWritesBothFiles) {
  const auto script = write("square.geo", kSquare);
  ASSERT_EQ(run({script.string(), "-2", "-view"}), 0) << err_.str();
  EXPECT_TRUE(std::filesystem::exists(dir_ / "square.msh"));
  EXPECT_NE(read(dir_ / "square.html").find("geomesh-mesh"), std::string::npos);
}

TEST_F(ViewCommand, HtmlIsAnOutputFormat) {
  const auto script = write("square.geo", kSquare);
  ASSERT_EQ(run({script.string(), "-2", "-o", (dir_ / "out.html").string()}), 0) << err_.str();
  EXPECT_NE(read(dir_ / "out.html").find("<!DOCTYPE html>"), std::string::npos);
  ASSERT_EQ(run({script.string(), "-2", "-format", "html", "-o", (dir_ / "f.page").string()}), 0)
      << err_.str();
  EXPECT_NE(read(dir_ / "f.page").find("geomesh-mesh"), std::string::npos);
}

TEST_F(ViewCommand, AMissingFileIsAnErrorAndNoPage) {
  EXPECT_EQ(run({"view", (dir_ / "missing.msh").string()}), 1);
  EXPECT_NE(err_.str().find("Error"), std::string::npos);
  EXPECT_NE(err_.str().find("missing.msh"), std::string::npos) << err_.str();
  EXPECT_FALSE(anyPage());
}

TEST_F(ViewCommand, AGarbageFileIsAnErrorAndNoPage) {
  const auto bad = write("bad.msh", "this is no mesh\n\x01\x02\x03");
  EXPECT_EQ(run({"view", bad.string()}), 1);
  EXPECT_NE(err_.str().find("bad.msh"), std::string::npos) << err_.str();
  const auto empty = write("empty.stl", "");
  EXPECT_EQ(run({"view", empty.string()}), 1);
  EXPECT_FALSE(anyPage());
}

TEST_F(ViewCommand, AScriptIsNotAMeshFile) {
  const auto script = write("square.geo", kSquare);
  EXPECT_EQ(run({"view", script.string()}), 1);
  EXPECT_NE(err_.str().find("-view"), std::string::npos) << err_.str();
  EXPECT_FALSE(anyPage());
}

}  // namespace
}  // namespace geomesh
