// Tests of OptionRegistry: defaults, old names, listing, suggestions, colours, reset.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <tuple>

#include "stdlib/colors.h"
#include "stdlib/build_info.h"
#include "stdlib/options.h"

namespace geomesh {
namespace {

TEST(OptionRegistry, RequiredDefaults) {
  OptionRegistry options;
  const std::pair<const char*, double> defaults[] = {
      {"Mesh.MeshSizeMin", 0},          {"Mesh.MeshSizeMax", 1e22},
      {"Mesh.MeshSizeFactor", 1},       {"Mesh.MeshSizeFromPoints", 1},
      {"Mesh.MeshSizeExtendFromBoundary", 1}, {"Mesh.MeshSizeFromCurvature", 0},
      {"Mesh.Algorithm", 6},            {"Mesh.Algorithm3D", 1},
      {"Mesh.Smoothing", 1},            {"Mesh.ElementOrder", 1},
      {"Mesh.SaveAll", 0},              {"Mesh.Binary", 0},
      {"Mesh.MshFileVersion", 4.1},     {"Mesh.RandomFactor", 1e-9},
      {"Mesh.RecombineAll", 0},         {"Mesh.Optimize", 1},
      {"General.NumThreads", 1},        {"General.Verbosity", 5},
      {"Geometry.Tolerance", 1e-8},     {"Geometry.AutoCoherence", 1},
      {"Mesh.Format", 10}};
  for (const auto& [name, value] : defaults) {
    ASSERT_TRUE(options.hasNumber(name)) << name;
    EXPECT_DOUBLE_EQ(options.number(name), value) << name;
  }
}

// The read-only build options describe this program's own build and the running executable.
TEST(OptionRegistry, BuildOptionsDescribeThisBuild) {
  OptionRegistry options;
  const std::string info = options.string("General.BuildInfo");
  EXPECT_EQ(info.rfind("Version: " GEOMESH_VERSION ";", 0), 0u) << info;
  EXPECT_NE(info.find("OCC version: 7."), std::string::npos) << info;
  EXPECT_NE(info.find("Compiler: "), std::string::npos) << info;
  EXPECT_NE(options.string("General.BuildOptions").find("OpenCASCADE"), std::string::npos);
  const std::string exe = options.string("General.ExecutableFileName");
  EXPECT_EQ(exe.substr(exe.rfind('/') + 1), "stdlib_tests") << exe;
}

TEST(OptionRegistry, EveryOptionHasHelpAndCoversTheThreeCategories) {
  OptionRegistry options;
  EXPECT_GT(options.all().size(), 500u);
  for (const auto& option : options.all()) {
    EXPECT_FALSE(option.help.empty()) << option.name;
    // A help line says what the option does, not just its name again.
    EXPECT_EQ(option.help.find(" setting: "), std::string::npos) << option.name;
  }
  EXPECT_TRUE(options.hasString("General.DefaultFileName"));
  EXPECT_TRUE(options.hasNumber("Geometry.OldNewReg"));
}

TEST(OptionRegistry, OldNamesAreAliases) {
  OptionRegistry options;
  options.setNumber("Mesh.CharacteristicLengthMin", 0.5);
  EXPECT_EQ(options.number("Mesh.MeshSizeMin"), 0.5);
  options.setNumber("Mesh.MeshSizeMax", 2);
  EXPECT_EQ(options.number("Mesh.CharacteristicLengthMax"), 2);
  for (const char* alias : {"Mesh.CharacteristicLengthFactor", "Mesh.CharacteristicLengthFromPoints",
                            "Mesh.CharacteristicLengthExtendFromBoundary"})
    EXPECT_TRUE(options.hasNumber(alias)) << alias;
  EXPECT_EQ(options.find("Mesh.CharacteristicLengthFactor")->name, "Mesh.MeshSizeFactor");
}

// Old names the reference still accepts, each with the option it stands for and its default.
TEST(OptionRegistry, EveryOldNameReachesItsOption) {
  OptionRegistry options;
  const std::tuple<const char*, const char*, double> aliases[] = {
      {"Mesh.MinimumCircleNodes", "Mesh.MinCircleNodes", 7},
      {"Mesh.MinimumCirclePoints", "Mesh.MinCircleNodes", 7},
      {"Mesh.MinimumCurveNodes", "Mesh.MinCurveNodes", 3},
      {"Mesh.MinimumCurvePoints", "Mesh.MinCurveNodes", 3},
      {"Mesh.MinimumLineNodes", "Mesh.MinLineNodes", 2},
      {"Mesh.MinimumElementsPerTwoPi", "Mesh.MeshSizeFromCurvature", 0},
      {"Mesh.CompoundCharacteristicLengthFactor", "Mesh.CompoundMeshSizeFactor", 0.5},
      {"Mesh.BoundaryLayerFanPoints", "Mesh.BoundaryLayerFanElements", 5},
      {"Mesh.StlRemoveDuplicateTriangles", "Mesh.StlRemoveBadTriangles", 0},
      {"Geometry.LineNumbers", "Geometry.CurveLabels", 0},
      {"Geometry.LineSelectWidth", "Geometry.CurveSelectWidth", 3},
      {"Geometry.OCCUnionUnify", "Geometry.OCCBooleanSimplify", 1},
      {"Geometry.Color.Lines", "Geometry.Color.Curves", 255}};
  for (const auto& [alias, name, value] : aliases) {
    ASSERT_NE(options.find(alias), nullptr) << alias;
    EXPECT_EQ(options.find(alias)->name, name) << alias;
    EXPECT_DOUBLE_EQ(options.number(alias), value) << alias;
  }
  options.setNumber("Mesh.MinimumCirclePoints", 12);
  EXPECT_EQ(options.number("Mesh.MinCircleNodes"), 12);
  EXPECT_EQ(options.number("Mesh.MinimumCircleNodes"), 12);
  EXPECT_EQ(options.find("Geometry.DoubleClickedLineCommand")->name,
            "Geometry.DoubleClickedCurveCommand");
  EXPECT_EQ(options.suggestions("Mesh.MinimumCircleNode").front(), "Mesh.MinimumCircleNodes");
}

// The listing names every old name of an option.
TEST(OptionRegistry, ListingShowsEveryOldName) {
  OptionRegistry options;
  const std::string line = optionListingLine(*options.find("Mesh.MinCircleNodes"));
  EXPECT_EQ(line.rfind("Mesh.MinCircleNodes = 7; // ", 0), 0u) << line;
  EXPECT_NE(line.find("(old name: Mesh.MinimumCircleNodes)"), std::string::npos) << line;
  EXPECT_NE(line.find("(old name: Mesh.MinimumCirclePoints)"), std::string::npos) << line;
}

TEST(OptionRegistry, UnknownNamesThrowAndAreCaseSensitive) {
  OptionRegistry options;
  EXPECT_THROW(options.number("Mesh.NoSuchOption"), std::out_of_range);
  EXPECT_THROW(options.setNumber("mesh.meshsizemin", 1), std::out_of_range);
  EXPECT_THROW(options.string("Mesh.MeshSizeMin"), std::out_of_range);
  EXPECT_FALSE(options.hasString("Mesh.MeshSizeMin"));
}

TEST(OptionRegistry, StringsAndColours) {
  OptionRegistry options;
  options.setString("Geometry.OCCTargetUnit", "M");
  EXPECT_EQ(options.string("Geometry.OCCTargetUnit"), "M");
  EXPECT_EQ(options.find("General.Color.Background")->type, OptionType::Color);
  EXPECT_TRUE(options.hasNumber("General.Color.Background"));
}

TEST(Colours, X11NamesAsScriptsWriteThem) {
  EXPECT_EQ(namedColor("Red"), 255 * 65536.0);
  EXPECT_EQ(namedColor("NavyBlue"), 128.0);
  EXPECT_EQ(namedColor("Gray"), 190 * 65793.0);
  EXPECT_EQ(namedColor("DarkOliveGreen3"), 162 * 65536.0 + 205 * 256 + 90);
  EXPECT_FALSE(namedColor("red"));
  EXPECT_FALSE(namedColor("Navy Blue"));
  EXPECT_GT(colorNames().size(), 600u);
}

TEST(OptionRegistry, SuggestsCloseNames) {
  OptionRegistry options;
  auto close = options.suggestions("Mesh.MeshSizeMn");
  ASSERT_FALSE(close.empty());
  EXPECT_EQ(close.front(), "Mesh.MeshSizeMin");
  EXPECT_TRUE(options.suggestions("Completely.Different").empty());
}

TEST(OptionRegistry, ResetRestoresDefaults) {
  OptionRegistry options;
  options.setNumber("Mesh.Algorithm", 5);
  options.reset();
  EXPECT_EQ(options.number("Mesh.Algorithm"), 6);
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST(OptionListing, LinesInScriptSyntax) {
  OptionRegistry options;
  EXPECT_EQ(optionListingLine(*options.find("Mesh.MeshSizeMin")),
            "Mesh.MeshSizeMin = 0; // lower bound on the element size "
            "(old name: Mesh.CharacteristicLengthMin)");
  EXPECT_EQ(optionListingLine(*options.find("General.Color.Background")).substr(0, 41),
            "General.Color.Background = {255,255,255};");
  options.setNumber("Mesh.MshFileVersion", 2.2);
  EXPECT_EQ(optionListingLine(*options.find("Mesh.MshFileVersion")).substr(0, 28),
            "Mesh.MshFileVersion = 2.2; /");
}

}  // namespace
}  // namespace geomesh
