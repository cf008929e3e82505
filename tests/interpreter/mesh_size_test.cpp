// Tests of MeshSize{points} = size: prescribed point sizes and rejected tags and sizes.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(MeshSize, SetsThePrescribedSizeOfPoints) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0, 0.1};\nPoint(2) = {1, 0, 0};\nPoint(3) = {0, 1, 0};\n"
          "MeshSize{1, 2} = 0.25;\nCharacteristic Length{3} = 0.5;\n");
  run.session.synchronize();
  const Model& model = run.session.model();
  ASSERT_NE(model.point(3), nullptr);
  EXPECT_EQ(model.point(1)->meshSize, 0.25);
  EXPECT_EQ(model.point(2)->meshSize, 0.25);
  EXPECT_EQ(model.point(3)->meshSize, 0.5);
  EXPECT_TRUE(run.log.warnings.empty());
}

TEST(MeshSize, AllPointsAtOnce) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0, 0.1};\nPoint(4) = {1, 0, 0};\nMeshSize{:} = 0.2;\n");
  run.session.synchronize();
  EXPECT_EQ(run.session.model().point(1)->meshSize, 0.2);
  EXPECT_EQ(run.session.model().point(4)->meshSize, 0.2);
}

TEST(MeshSize, RejectsBadTagsAndSizes) {
  EXPECT_NE(errorOf("Point(1) = {0, 0, 0};\nMeshSize{1.5} = 0.1;").find("test.geo:2:"),
            std::string::npos);
  EXPECT_NE(errorOf("Point(1) = {0, 0, 0};\nMeshSize{1} = -1;").find("test.geo:2:15: error:"),
            std::string::npos)
      << errorOf("Point(1) = {0, 0, 0};\nMeshSize{1} = -1;");
}

}  // namespace
}  // namespace geomesh::testing
