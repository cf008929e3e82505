// A 100 MB script is read and its error, on the very last line, is reported with that line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/run.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh {
namespace {

TEST(LargeInput, HundredMegabyteScriptReportsItsLastLine) {
  const fs::path dir = scratch::path("large-input");
  fs::create_directories(dir);
  const fs::path script = dir / "huge.geo";
  const std::string line = "x = 1 + 2 * 3; // padding padding padding padding padding padding\n";
  const std::size_t lines = (100u << 20) / line.size() + 1;
  {
    std::ofstream out(script, std::ios::binary);
    for (std::size_t i = 0; i < lines; ++i) out << line;
    out << "y = (x + ;\n";
  }
  ASSERT_GE(fs::file_size(script), 100u << 20);
  std::ostringstream sout, serr;
  EXPECT_EQ(runGeomesh({script.string(), "-2", "-o", (dir / "huge.msh").string()}, sout, serr), 1);
  const std::string where = "huge.geo:" + std::to_string(lines + 1) + ":10: error:";
  EXPECT_NE(serr.str().find(where), std::string::npos) << serr.str().substr(0, 2000);
  EXPECT_FALSE(fs::exists(dir / "huge.msh"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace geomesh
