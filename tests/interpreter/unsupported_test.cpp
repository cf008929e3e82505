// Statements not carried out yet warn once at their location; the Memory constant is measured.
#include <gtest/gtest.h>

#include <algorithm>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

// Statements the kernel cannot carry out yet: each parses, warns at its location, and the
// script goes on.
constexpr const char* kStatements[] = {
    "Smoother Surface{1} = 3;",
    "Reverse Surface{1};",
    "Save \"x.eps\";",
    "RefineMesh;",
    "Merge \"whatever.wrl\";",
    "Periodic Surface{2} = {1};",
};

TEST(Unsupported, EachStatementWarnsOnceAtItsLocation) {
  for (const char* statement : kStatements) {
    ScriptRun run;
    run.run(std::string("Point(1) = {0,0,0}; Point(2) = {1,0,0}; Point(3) = {0,1,0};\n") +
            statement + "\nPrintf(\"after\");\n");
    EXPECT_EQ(run.out.str(), "after\n") << statement;
    ASSERT_EQ(run.log.warnings.size(), 1u) << statement;
    EXPECT_EQ(run.log.warnings[0].substr(0, 9), "test.geo:") << statement;
    EXPECT_NE(run.log.warnings[0].find("not supported yet"), std::string::npos)
        << run.log.warnings[0];
  }
}

TEST(Unsupported, WarningsNameTheStatement) {
  ScriptRun run;
  run.run("Point{3} In Volume{1, 2} Using Progression 2;\nRefineMesh;\n");
  ASSERT_EQ(run.log.warnings.size(), 2u);
  EXPECT_EQ(run.log.warnings[0],
            "test.geo:1:1: warning: 'Point In Volume' is not supported yet; ignored");
  EXPECT_EQ(run.log.warnings[1],
            "test.geo:2:1: warning: 'RefineMesh' is not supported yet; ignored");
}

TEST(Unsupported, AStatementInALoopWarnsOnce) {
  ScriptRun run;
  run.run("For i In {1:5}\n  Smoother Surface{1} = 3;\nEndFor\n");
  EXPECT_EQ(run.log.warnings.size(), 1u);
}

TEST(Unsupported, BuiltInFactoryIsAccepted) {
  ScriptRun run;
  run.run("SetFactory(\"Built-in\");\n");
  EXPECT_TRUE(run.log.warnings.empty());
}

// The OpenCASCADE factory and its boxes are no longer "not supported yet" (set_factory_test);
// an unknown factory still is.
TEST(Unsupported, OpenCascadeFactoryAndBoxesAreAccepted) {
  ScriptRun run;
  run.run("SetFactory(\"OpenCASCADE\");\nBox(11) = {0, 0, 0, 1, 1, 1};\n");
  EXPECT_TRUE(run.log.warnings.empty());
  run.run("SetFactory(\"Parasolid\");\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_NE(run.log.warnings[0].find("not supported yet"), std::string::npos);
}

// OpenCASCADE's statements under the built-in factory: each warns that it needs the other
// factory, at its location, and the script goes on (tests/interpreter/occ_statements_test.cpp
// has them under SetFactory("OpenCASCADE")).
TEST(Unsupported, OpenCascadeStatementsNeedTheirFactory) {
  constexpr const char* kOpenCascadeOnly[] = {
      "Circle(5) = {0, 0, 0, 0.5};",
      "v() = BooleanUnion{ Volume{10}; Delete; }{ Volume{11}; Delete; };",
      "BooleanDifference(12) = { Volume{10}; Delete; }{ Volume{11}; Delete; };",
      "Sphere(1) = {0, 0, 0, 1};",
  };
  for (const char* statement : kOpenCascadeOnly) {
    ScriptRun run;
    run.run(std::string("Point(1) = {0,0,0};\n") + statement + "\nPrintf(\"after\");\n");
    EXPECT_EQ(run.out.str(), "after\n") << statement;
    ASSERT_EQ(run.log.warnings.size(), 1u) << statement;
    EXPECT_EQ(run.log.warnings[0].substr(0, 11), "test.geo:2:") << statement;
    EXPECT_NE(run.log.warnings[0].find("needs SetFactory(\"OpenCASCADE\"); ignored"),
              std::string::npos)
        << run.log.warnings[0];
  }
}

TEST(SystemConstants, MemoryIsMeasured) {
  EXPECT_EQ(printed("Printf(\"%g %g\", Memory > 0, TotalMemory >= Memory);"), "1 1\n");
  EXPECT_EQ(printed("Printf(\"%g\", Cpu >= 0);"), "1\n");
}

}  // namespace
}  // namespace geomesh::testing
