// The include graph follows the layers written in docs/architecture.md: a file includes only
// headers of its own room or of rooms listed before it, and private rooms stay private.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace geomesh {
namespace {

namespace fs = std::filesystem;

// The rooms as the architecture document lists them: one level per line of its ```layers
// block (rooms on one line may not include each other), `!` marking a private room, and the
// files of its ```layering-exceptions block that may include private rooms.
struct Layers {
  std::map<std::string, int> level;  // room -> level (0 first)
  std::set<std::string> privateRooms;
  std::set<std::string> exceptions;  // files allowed to include a private room
};

std::vector<std::string> fencedBlock(const std::string& document, const std::string& name) {
  std::istringstream in(document);
  std::vector<std::string> lines;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside && line == "```" + name) {
      inside = true;
    } else if (inside && line == "```") {
      return lines;
    } else if (inside) {
      lines.push_back(line);
    }
  }
  return lines;
}

Layers readLayers(const fs::path& document) {
  std::ifstream in(document);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  Layers layers;
  int level = 0;
  for (const std::string& line : fencedBlock(text, "layers")) {
    std::istringstream words(line);
    std::string room;
    while (words >> room) {
      const bool isPrivate = room.back() == '!';
      if (isPrivate) room.pop_back();
      layers.level[room] = level;
      if (isPrivate) layers.privateRooms.insert(room);
    }
    ++level;
  }
  for (const std::string& line : fencedBlock(text, "layering-exceptions"))
    if (!line.empty()) layers.exceptions.insert(line);
  return layers;
}

// The room of a path: its longest listed folder prefix; empty when none.
std::string roomOf(const Layers& layers, const std::string& path) {
  std::string best;
  for (const auto& [room, level] : layers.level)
    if (path.rfind(room + "/", 0) == 0 && room.size() > best.size()) best = room;
  return best;
}

const fs::path kRoot = GEOMESH_SOURCE_DIR;
const std::set<std::string> kNotSource = {"tests", "bench", "tutorials", "docs", "scripts",
                                          "cmake"};

std::vector<std::string> sourceFiles() {
  std::vector<std::string> files;
  for (auto it = fs::recursive_directory_iterator(kRoot); it != fs::end(it); ++it) {
    const std::string relative = fs::relative(it->path(), kRoot).generic_string();
    if (it->is_directory()) {
      const std::string top = relative.substr(0, relative.find('/'));
      if (kNotSource.count(top) || top.rfind("build", 0) == 0 || top.front() == '.')
        it.disable_recursion_pending();
      continue;
    }
    const std::string ext = it->path().extension().string();
    if (relative.find('/') != std::string::npos &&
        (ext == ".h" || ext == ".cpp" || ext == ".y" || ext == ".re" || ext == ".in"))
      files.push_back(relative);
  }
  return files;
}

struct Include {
  int line;
  std::string header;
};

std::vector<Include> projectIncludes(const std::string& file) {
  static const std::regex kInclude(R"(^\s*#\s*include\s+"([^"]+)\")");
  std::ifstream in(kRoot / file);
  std::vector<Include> includes;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::smatch m;
    if (std::regex_search(line, m, kInclude)) includes.push_back({n, m[1]});
  }
  return includes;
}

// What is wrong with `file` including `header`; empty when allowed.
std::string violation(const Layers& layers, const std::string& file, const std::string& header) {
  if (header.find('/') == std::string::npos) return {};  // generated or local header
  const std::string from = roomOf(layers, file);
  const std::string to = roomOf(layers, header);
  if (to.empty()) return "includes a header outside every room";
  if (to == from) return {};
  if (layers.privateRooms.count(to)) {
    // The one place that chooses a factory may reach into the private rooms, and only it.
    if (layers.exceptions.count(file)) return {};
    return "reaches into the private room " + to;
  }
  if (layers.level.at(to) >= layers.level.at(from))
    return "goes up the stack or sideways: " + from + " may not include " + to;
  return {};
}

TEST(Layering, TheDocumentListsTheRooms) {
  const Layers layers = readLayers(kRoot / "docs/architecture.md");
  EXPECT_GE(layers.level.size(), 10u);
  EXPECT_TRUE(layers.level.count("mesh/core"));
  EXPECT_TRUE(layers.privateRooms.count("kernel/geo"));
}

TEST(Layering, EverySourceFileIsInARoom) {
  const Layers layers = readLayers(kRoot / "docs/architecture.md");
  const std::vector<std::string> files = sourceFiles();
  EXPECT_GT(files.size(), 100u);
  for (const std::string& file : files)
    EXPECT_FALSE(roomOf(layers, file).empty())
        << file << " is in no room of docs/architecture.md: add its folder to the layers";
}

TEST(Layering, IncludesGoDownTheStackOnly) {
  const Layers layers = readLayers(kRoot / "docs/architecture.md");
  for (const std::string& file : sourceFiles()) {
    if (roomOf(layers, file).empty()) continue;
    for (const Include& include : projectIncludes(file)) {
      const std::string why = violation(layers, file, include.header);
      EXPECT_TRUE(why.empty()) << file << ":" << include.line << ": #include \""
                               << include.header << "\" " << why;
    }
  }
}

// Every source file opens with a comment saying what it holds.
TEST(Layering, EverySourceFileSaysWhatItHolds) {
  for (const std::string& file : sourceFiles()) {
    std::ifstream in(kRoot / file);
    std::string line;
    while (std::getline(in, line) && line.find_first_not_of(" \t\r") == std::string::npos) {
    }
    const std::size_t start = line.find_first_not_of(" \t");
    const bool comment = start != std::string::npos &&
                         (line.compare(start, 2, "//") == 0 || line.compare(start, 2, "/*") == 0);
    EXPECT_TRUE(comment) << file << " does not open with a comment saying what it holds";
  }
}

// The rule itself: a test layering in which every kind of violation occurs.
TEST(Layering, TheRuleCatchesEachKindOfViolation) {
  Layers layers;
  layers.level = {{"low", 0}, {"mid", 1}, {"peer", 1}, {"mid/secret", 1}, {"high", 2}};
  layers.privateRooms = {"mid/secret"};
  layers.exceptions = {"high/selection.cpp"};
  EXPECT_EQ(violation(layers, "mid/a.cpp", "low/b.h"), "");
  EXPECT_EQ(violation(layers, "mid/a.cpp", "mid/c.h"), "");
  EXPECT_NE(violation(layers, "low/a.cpp", "mid/b.h"), "");          // up the stack
  EXPECT_NE(violation(layers, "mid/a.cpp", "peer/b.h"), "");         // sideways
  EXPECT_NE(violation(layers, "high/a.cpp", "mid/secret/b.h"), "");  // private
  EXPECT_EQ(violation(layers, "high/selection.cpp", "mid/secret/b.h"), "");
  EXPECT_NE(violation(layers, "high/a.cpp", "nowhere/b.h"), "");
}

}  // namespace
}  // namespace geomesh
