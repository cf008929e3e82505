// `Mesh n;` in a script: a meshing failure points at the statement that defined the entity,
// quoting the script text as it was run (not a file on disk).
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(MeshStatement, AFailurePointsAtTheDefiningStatementOfTheScriptText) {
  const std::string error = errorOf(R"(Point(1) = {0, 0, 0, 0.1}; Point(2) = {3, 0, 0, 0.1};
Point(3) = {0, 1, 0, 0.1}; Point(4) = {1, 2, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
  Plane Surface(1) = {1};
Mesh 2;
)");
  EXPECT_EQ(error.rfind("test.geo:5:3: error: ", 0), 0u) << error;
  EXPECT_NE(error.find("surface 1"), std::string::npos) << error;
  EXPECT_NE(error.find("\n  Plane Surface(1) = {1};\n  ^"), std::string::npos) << error;
}

TEST(MeshStatement, ADimensionOutOfRangeIsRefusedAtItsValue) {
  EXPECT_EQ(firstLineOf("Mesh 4;"), "test.geo:1:6: error: 'Mesh' takes a dimension 0, 1, 2 or 3");
}

}  // namespace
}  // namespace geomesh::testing
