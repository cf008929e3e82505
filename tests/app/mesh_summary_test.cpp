// The run's summary lines for quadrangle and hexahedron meshes: irregular vertices, the share
// of the volume in hexahedra.
#include <gtest/gtest.h>

#include <string>

#include "api/meshing.h"
#include "app/mesh_summary.h"
#include "tests/interpreter/script_runner.h"

namespace geomesh::testing {
namespace {

MeshSummary summaryOf(const std::string& script, int dim) {
  ScriptRun run;
  run.run(script);
  api::generate(run.session, dim);
  return summarizeMesh(run.session.model(), run.session.mesh());
}

constexpr const char* kSquare =
    "Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1};\n"
    "Point(4) = {0, 1, 0, 0.1};\nLine(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
    "Line(4) = {4, 1};\nCurve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n";

TEST(MeshSummary, AStructuredQuadrangleGridHasNoIrregularVertex) {
  const MeshSummary s = summaryOf(std::string(kSquare) +
                                      "Transfinite Curve{1, 2, 3, 4} = 11;\n"
                                      "Transfinite Surface{1};\nRecombine Surface{1};\n",
                                  2);
  EXPECT_EQ(s.interiorVertices, 81u);  // 9 x 9 inside an 11 x 11 grid
  EXPECT_EQ(s.irregularVertices, 0u);
  EXPECT_EQ(formatQuadStructure(s),
            "quadrangles: 0 of 81 interior vertices irregular (not 4 edges)");
}

TEST(MeshSummary, ARecombinedMeshCountsItsIrregularVertices) {
  const MeshSummary s = summaryOf(std::string(kSquare) + "Recombine Surface{1};\n", 2);
  EXPECT_GT(s.interiorVertices, 60u);
  EXPECT_GT(s.irregularVertices, 0u);  // an unstructured quadrangle mesh has some
  EXPECT_LT(s.irregularVertices, s.interiorVertices / 2);
  // Triangles only: no quadrangle line at all, nothing counted.
  const MeshSummary triangles = summaryOf(kSquare, 2);
  EXPECT_EQ(triangles.interiorVertices, 0u);
  EXPECT_EQ(formatQuadStructure(triangles), "");
}

TEST(MeshSummary, TheShareOfTheVolumeInHexahedra) {
  // A unit cube of hexahedra beside a unit cube of tetrahedra: half the volume.
  const MeshSummary s = summaryOf(
      std::string(kSquare) +
          "Recombine Surface{1};\nExtrude {0, 0, 1} { Surface{1}; Layers{5}; Recombine; }\n"
          "Point(101) = {2, 0, 0, 0.25}; Point(102) = {3, 0, 0, 0.25};\n"
          "Point(103) = {3, 1, 0, 0.25}; Point(104) = {2, 1, 0, 0.25};\n"
          "Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104};\n"
          "Line(104) = {104, 101};\nCurve Loop(101) = {101, 102, 103, 104};\n"
          "Plane Surface(101) = {101};\nExtrude {0, 0, 1} { Surface{101}; }\n",
      3);
  EXPECT_NEAR(s.volume, 2, 1e-9);
  EXPECT_NEAR(s.hexahedraVolume, 1, 1e-9);
  EXPECT_EQ(formatHexShare(s), "hexahedra: 50% of the volume");
  EXPECT_EQ(formatHexShare(summaryOf(kSquare, 2)), "");
}

}  // namespace
}  // namespace geomesh::testing
