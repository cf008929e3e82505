// The same script and options give byte-identical output, run after run, whatever the number
// of threads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/run.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh {
namespace {

std::string meshBytes(const std::string& script, const std::vector<std::string>& extra,
                      const std::string& tag) {
  const fs::path out = scratch::path("determinism-" + tag + ".msh");
  std::vector<std::string> args{script, "-2", "-v", "0", "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  std::ostringstream sout, serr;
  EXPECT_EQ(runGeomesh(args, sout, serr), 0) << serr.str();
  std::ifstream in(out, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove(out);
  return bytes;
}

TEST(Determinism, SameScriptSameBytesAcrossRunsAndThreadCounts) {
  const std::string script = std::string(GEOMESH_SOURCE_DIR) + "/tutorials/t1.geo";
  const std::string first = meshBytes(script, {"-nt", "1"}, "a");
  ASSERT_GT(first.size(), 1000u);
  EXPECT_EQ(meshBytes(script, {"-nt", "1"}, "b"), first);
  EXPECT_EQ(meshBytes(script, {"-nt", "2"}, "c"), first);
}

TEST(Determinism, HolesScriptIsStable) {
  const std::string script =
      std::string(GEOMESH_SOURCE_DIR) + "/tests/golden/scripts/square_holes.geo";
  const std::string first = meshBytes(script, {}, "d");
  ASSERT_GT(first.size(), 1000u);
  EXPECT_EQ(meshBytes(script, {"-nt", "2"}, "e"), first);
}

TEST(Determinism, PartitionedFilesDoNotDependOnThreads) {
  const std::string script = std::string(GEOMESH_SOURCE_DIR) + "/tutorials/t1.geo";
  const std::string first = meshBytes(script, {"-part", "5", "-nt", "1"}, "f");
  ASSERT_NE(first.find("$PartitionedEntities"), std::string::npos);
  EXPECT_EQ(meshBytes(script, {"-part", "5", "-nt", "2"}, "g"), first);
  EXPECT_EQ(meshBytes(script, {"-part", "5", "-nt", "1"}, "h"), first);
}

}  // namespace
}  // namespace geomesh
