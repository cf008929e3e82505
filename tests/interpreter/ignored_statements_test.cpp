// The session records the statements a script skipped as not supported yet, each place once.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(IgnoredStatements, UnsupportedStatementsAreRecordedInOrder) {
  ScriptRun run;
  run.run("a = 1;\nSetFactory(\"Parasolid\");\n"
          "For i In {1:3}\n  Smoother Surface{i} = 3;\nEndFor\n");
  EXPECT_EQ(run.session.ignoredStatementCount(), 2u);
  EXPECT_EQ(run.session.firstIgnoredStatement(), (SourceLocation{"test.geo", 2, 1}));
}

TEST(IgnoredStatements, UnsupportedShapeOperationsAndMergesCount) {
  ScriptRun run;
  run.run("v() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };\n"
          "Merge \"part.dxf\";\n");  // STEP files are read now (occ_statements_test)
  EXPECT_EQ(run.session.ignoredStatementCount(), 2u);
  EXPECT_EQ(run.session.firstIgnoredStatement()->line, 1);
}

TEST(IgnoredStatements, SupportedStatementsAndOtherWarningsAreNotRecorded) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0};\nMesh.NoSuchOption = 1;\nSave \"shot.eps\";\n");
  EXPECT_EQ(run.log.warnings.size(), 2u);
  EXPECT_EQ(run.session.ignoredStatementCount(), 0u);
  EXPECT_FALSE(run.session.firstIgnoredStatement());
}

}  // namespace
}  // namespace geomesh::testing
