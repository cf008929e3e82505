// Tests of parseCommandLine: files, dimensions, size and algorithm flags, -setnumber, errors.
#include <gtest/gtest.h>

#include "app/command_line.h"

namespace geomesh {
namespace {

TEST(CommandLine, ReadsFileDimensionAndOutput) {
  CommandLine cl = parseCommandLine({"plate.geo", "-2", "-o", "out.msh"});
  ASSERT_EQ(cl.files.size(), 1u);
  EXPECT_EQ(cl.files[0], "plate.geo");
  ASSERT_TRUE(cl.dimension.has_value());
  EXPECT_EQ(*cl.dimension, 2);
  EXPECT_EQ(cl.output, "out.msh");
}

TEST(CommandLine, EveryDimensionFlag) {
  for (int d = 0; d <= 3; ++d) {
    CommandLine cl = parseCommandLine({"-" + std::to_string(d), "a.geo"});
    EXPECT_EQ(cl.dimension.value(), d);
  }
  EXPECT_FALSE(parseCommandLine({"a.geo"}).dimension.has_value());
}

TEST(CommandLine, SizeFlagsBecomeOptionsInOrder) {
  CommandLine cl = parseCommandLine({"a.geo", "-clmin", "0.01", "-clmax", "0.5", "-clscale", "2"});
  ASSERT_EQ(cl.numberOptions.size(), 3u);
  EXPECT_EQ(cl.numberOptions[0].first, "Mesh.MeshSizeMin");
  EXPECT_DOUBLE_EQ(cl.numberOptions[0].second, 0.01);
  EXPECT_EQ(cl.numberOptions[1].first, "Mesh.MeshSizeMax");
  EXPECT_DOUBLE_EQ(cl.numberOptions[1].second, 0.5);
  EXPECT_EQ(cl.numberOptions[2].first, "Mesh.MeshSizeFactor");
  EXPECT_DOUBLE_EQ(cl.numberOptions[2].second, 2);
}

TEST(CommandLine, ThreadsVerbosityAndFormat) {
  CommandLine cl = parseCommandLine({"a.geo", "-nt", "4", "-v", "0", "-format", "msh22"});
  EXPECT_EQ(cl.verbosity, 0);
  EXPECT_EQ(cl.format, "msh22");
  ASSERT_EQ(cl.numberOptions.size(), 1u);
  EXPECT_EQ(cl.numberOptions[0].first, "General.NumThreads");
  EXPECT_DOUBLE_EQ(cl.numberOptions[0].second, 4);
}

TEST(CommandLine, SetNumberAndSetString) {
  CommandLine cl = parseCommandLine({"-setnumber", "n", "12", "-setstring", "s", "text", "a.geo"});
  ASSERT_EQ(cl.setNumbers.size(), 1u);
  EXPECT_EQ(cl.setNumbers[0].first, "n");
  EXPECT_DOUBLE_EQ(cl.setNumbers[0].second, 12);
  ASSERT_EQ(cl.setStrings.size(), 1u);
  EXPECT_EQ(cl.setStrings[0].second, "text");
  EXPECT_EQ(cl.files, std::vector<std::string>{"a.geo"});
}

TEST(CommandLine, AlgorithmNames) {
  CommandLine cl = parseCommandLine({"-algo", "del2d", "a.geo"});
  ASSERT_EQ(cl.numberOptions.size(), 1u);
  EXPECT_EQ(cl.numberOptions[0].first, "Mesh.Algorithm");
  EXPECT_DOUBLE_EQ(cl.numberOptions[0].second, 5);
  EXPECT_THROW(parseCommandLine({"-algo", "nonsense"}), CommandLineError);
}

TEST(CommandLine, UnknownFlagIsNamed) {
  try {
    parseCommandLine({"a.geo", "-frobnicate"});
    FAIL() << "no error";
  } catch (const CommandLineError& e) {
    EXPECT_NE(std::string(e.what()).find("-frobnicate"), std::string::npos);
  }
}

TEST(CommandLine, MissingOrBadValuesAreErrors) {
  EXPECT_THROW(parseCommandLine({"a.geo", "-o"}), CommandLineError);
  EXPECT_THROW(parseCommandLine({"a.geo", "-clmax"}), CommandLineError);
  EXPECT_THROW(parseCommandLine({"a.geo", "-clmax", "big"}), CommandLineError);
  EXPECT_THROW(parseCommandLine({"a.geo", "-clmax", "nan"}), CommandLineError);
  EXPECT_THROW(parseCommandLine({"a.geo", "-setnumber", "x"}), CommandLineError);
}

TEST(CommandLine, HelpAndVersion) {
  EXPECT_TRUE(parseCommandLine({"-help"}).help);
  EXPECT_TRUE(parseCommandLine({"-version"}).version);
  EXPECT_NE(commandLineHelp().find("-clscale"), std::string::npos);
}

}  // namespace
}  // namespace geomesh
