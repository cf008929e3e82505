// Tutorial pictures: each tutorial of tests/golden/tutorials is meshed as its golden test
// meshes it (the arguments of NAME.expected), written as a PNG picture of the size of the
// committed tutorials/pictures/NAME.png, and compared with that picture: both decoded, at most
// 0.5% of the pixels may differ by more than a small threshold, so that rounding in another
// build passes and a changed mesh or renderer does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "app/run.h"
#include "golden_expectation.h"
#include "io/rgb_image.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh::golden {
namespace {

constexpr int kChannelThreshold = 40;     // a pixel differs when a channel differs by more
constexpr double kDifferingShare = 0.005;  // of the pixels that may differ
constexpr const char* kRefresh =
    "run scripts/tutorial-pictures.sh BUILD_DIR/bin/geomesh to refresh the pictures";

struct Tutorial {
  std::string name;
  fs::path expected;
};

void PrintTo(const Tutorial& t, std::ostream* os) { *os << t.name; }

std::vector<Tutorial> tutorials() {
  std::vector<Tutorial> result;
  for (const auto& entry :
       fs::directory_iterator(fs::path(GEOMESH_SOURCE_DIR) / "tests" / "golden" / "tutorials"))
    if (entry.path().extension() == ".expected")
      result.push_back({entry.path().stem().string(), entry.path()});
  std::sort(result.begin(), result.end(),
            [](const Tutorial& a, const Tutorial& b) { return a.name < b.name; });
  return result;
}

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// How many pixels differ by more than the threshold in some channel.
std::size_t differingPixels(const RgbImage& a, const RgbImage& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); i += 3) {
    bool differs = false;
    for (std::size_t c = 0; c < 3; ++c)
      differs = differs || std::abs(a.pixels[i + c] - b.pixels[i + c]) > kChannelThreshold;
    n += differs;
  }
  return n;
}

class TutorialPicture : public testing::TestWithParam<Tutorial> {};

TEST_P(TutorialPicture, IsUpToDate) {
  const std::string& name = GetParam().name;
  const GoldenCase c = readExpectations(GetParam().expected.string());
  if (c.exitStatus != 0) GTEST_SKIP() << name << " is expected to fail";
  const fs::path source(GEOMESH_SOURCE_DIR);
  const fs::path committedPath = source / "tutorials" / "pictures" / (name + ".png");
  ASSERT_TRUE(fs::exists(committedPath))
      << "tutorials/pictures/" << name << ".png is missing: " << kRefresh;
  const RgbImage committed = decodePng(readBytes(committedPath));

  const fs::path fresh = scratch::path("tutorial-picture-" + name + ".png");
  fs::remove(fresh);
  std::vector<std::string> args = c.args;
  args.insert(args.end(), {(source / "tutorials" / (name + ".geo")).string(), "-o",
                           fresh.string(), "-setnumber", "Print.Width",
                           std::to_string(committed.width), "-setnumber", "Print.Height",
                           std::to_string(committed.height)});
  std::ostringstream out, err;
  ASSERT_EQ(runGeomesh(args, out, err), 0) << "stderr:\n" << err.str();
  const RgbImage rendered = decodePng(readBytes(fresh));
  fs::remove(fresh);

  ASSERT_EQ(rendered.width, committed.width);
  ASSERT_EQ(rendered.height, committed.height);
  const std::size_t differing = differingPixels(rendered, committed);
  const std::size_t total = std::size_t(committed.width) * committed.height;
  EXPECT_LE(double(differing), kDifferingShare * double(total))
      << "tutorials/pictures/" << name << ".png is out of date: " << differing << " of its "
      << total << " pixels differ from a fresh picture of tutorials/" << name << ".geo; "
      << kRefresh;
}

std::string caseName(const testing::TestParamInfo<Tutorial>& info) {
  std::string n = info.param.name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Tutorials, TutorialPicture, testing::ValuesIn(tutorials()), caseName);

// The size of a picture: Print.Width and Print.Height (set by -setnumber or in the script)
// when positive, else General.GraphicsWidth and General.GraphicsHeight.
TEST(PictureCommandLine, SizeComesFromThePrintAndGraphicsOptions) {
  const fs::path script = scratch::path("picture-square.geo");
  std::ofstream(script) << "Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5};\n"
                           "Point(3) = {1, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};\n"
                           "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
                           "Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4};\n"
                           "Plane Surface(1) = {1}; Physical Curve(1) = {1};\n"
                           "General.GraphicsWidth = 300; Print.Height = 200;\n";
  const fs::path picture = scratch::path("picture-square.png");
  const auto sizeOf = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {script.string(), "-2", "-o", picture.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    std::ostringstream out, err;
    EXPECT_EQ(runGeomesh(args, out, err), 0) << err.str();
    // A picture shows every element: no warning about elements outside physical groups.
    EXPECT_EQ(err.str().find("leaves out"), std::string::npos) << err.str();
    const RgbImage image = decodePng(readBytes(picture));
    fs::remove(picture);
    return std::to_string(image.width) + "x" + std::to_string(image.height);
  };
  EXPECT_EQ(sizeOf({}), "300x200");
  EXPECT_EQ(sizeOf({"-format", "png", "-setnumber", "Print.Width", "120"}), "120x200");
  // Without -o, -format png writes the script's name with the extension of pictures.
  std::ostringstream out, err;
  ASSERT_EQ(runGeomesh({script.string(), "-2", "-format", "png"}, out, err), 0) << err.str();
  EXPECT_EQ(decodePng(readBytes(picture)).width, 300);
  EXPECT_FALSE(fs::exists(scratch::path("picture-square.msh")));
  fs::remove(picture);
  fs::remove(script);
}

}  // namespace
}  // namespace geomesh::golden
