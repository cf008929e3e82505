// Random byte mutations of ordinary scripts: each run ends either in success or with a
// diagnostic naming FILE:LINE, exits 0 or 1, and writes no mesh after an error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include "app/run.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh {
namespace {

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One to four random edits: replace, insert or delete a byte (any byte value).
std::string mutate(std::string text, std::mt19937& rng) {
  std::uniform_int_distribution<int> edits(1, 4), kind(0, 2), byte(0, 255);
  for (int e = edits(rng); e > 0 && !text.empty(); --e) {
    std::uniform_int_distribution<std::size_t> at(0, text.size() - 1);
    const std::size_t i = at(rng);
    const char c = static_cast<char>(byte(rng));
    switch (kind(rng)) {
      case 0: text[i] = c; break;
      case 1: text.insert(text.begin() + static_cast<std::ptrdiff_t>(i), c); break;
      default: text.erase(i, 1); break;
    }
  }
  return text;
}

TEST(Mutations, EveryMutantSucceedsOrFailsWithALocatedDiagnostic) {
  const fs::path source(GEOMESH_SOURCE_DIR);
  const std::vector<std::string> originals = {
      readFile(source / "tutorials" / "t1.geo"),
      readFile(source / "tests" / "golden" / "scripts" / "square_holes.geo"),
      readFile(source / "tests" / "golden" / "scripts" / "graded.geo"),
      readFile(source / "tests" / "golden" / "scripts" / "printf.geo"),
  };
  const fs::path dir = scratch::path("mutations");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path script = dir / "mutant.geo";
  const fs::path mesh = dir / "mutant.msh";
  const std::regex located("mutant\\.geo:[0-9]+:[0-9]+: error: ");
  std::mt19937 rng(20261122);
  int failures = 0;
  for (int n = 0; n < 300; ++n) {
    const std::string text = mutate(originals[static_cast<std::size_t>(n) % originals.size()], rng);
    std::ofstream(script, std::ios::binary) << text;
    fs::remove(mesh);
    std::ostringstream out, err;
    // Mutated sizes can ask for very fine meshes: keep each run small.
    const int status = runGeomesh(
        {script.string(), "-2", "-clmin", "0.01", "-v", "1", "-o", mesh.string()}, out, err);
    ASSERT_TRUE(status == 0 || status == 1) << "mutant " << n << ":\n" << text;
    if (status == 1) {
      ++failures;
      EXPECT_TRUE(std::regex_search(err.str(), located))
          << "mutant " << n << " failed without FILE:LINE:\n" << err.str() << "\n" << text;
      EXPECT_FALSE(fs::exists(mesh)) << "mutant " << n << " wrote a mesh after an error";
    } else {
      EXPECT_TRUE(fs::exists(mesh)) << "mutant " << n << " succeeded without a mesh";
    }
  }
  // Most mutants are broken; some stay valid. Both paths must have been exercised.
  EXPECT_GT(failures, 100);
  EXPECT_LT(failures, 300);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace geomesh
