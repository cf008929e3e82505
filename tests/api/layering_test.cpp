// The library order holds in the sources: grammar < kernel < mesh < io < api < interpreter <
// app. A module includes only modules below it, so api/ never includes the interpreter.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace geomesh {
namespace {

// "file: #include line" for each include of a folder in `forbidden` by a file of `module`.
std::vector<std::string> includesOf(const std::string& module,
                                    const std::vector<std::string>& forbidden) {
  std::vector<std::string> found;
  const fs::path root = fs::path(GEOMESH_SOURCE_DIR) / module;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".h" && ext != ".cpp") continue;
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);)
      for (const std::string& folder : forbidden)
        if (line.rfind("#include \"" + folder + "/", 0) == 0)
          found.push_back(entry.path().filename().string() + ": " + line);
  }
  return found;
}

TEST(Layering, ApiIncludesNeitherTheInterpreterNorTheApp) {
  EXPECT_EQ(includesOf("api", {"interpreter", "app"}), std::vector<std::string>{});
}

TEST(Layering, IoAndBelowIncludeNothingAbove) {
  EXPECT_EQ(includesOf("io", {"api", "interpreter", "app"}), std::vector<std::string>{});
  EXPECT_EQ(includesOf("mesh", {"io", "api", "interpreter", "app"}), std::vector<std::string>{});
  EXPECT_EQ(includesOf("grammar", {"kernel", "mesh", "io", "api", "interpreter", "app"}),
            std::vector<std::string>{});
}

}  // namespace
}  // namespace geomesh
