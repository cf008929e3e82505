// SetOrder n; and Mesh.ElementOrder in scripts: curved meshes of OpenCASCADE solids, every
// element valid, and the located errors for orders that cannot be made.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/high_order/jacobian.h"
#include "script_runner.h"

namespace geomesh::testing {
namespace {

struct Tally {
  std::size_t elements = 0, invalid = 0;
  double volume = 0;
  std::map<ElementType, std::size_t> types;
};

Tally tally(const Mesh& mesh) {
  Tally t;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks) {
      if (dimension(b.type) == 0) continue;
      t.types[b.type] += b.size();
      for (std::size_t e = 0; e < b.size(); ++e) {
        std::vector<Vec3> x;
        for (NodeIndex n : b.element(e)) x.push_back(mesh.node(n));
        ++t.elements;
        if (jacobianRange(b.type, x).min <= 0) ++t.invalid;
        if (dimension(b.type) == 3) t.volume += elementMeasure(b.type, x);
      }
    }
  return t;
}

TEST(SetOrderStatement, ASphericalShellAtOrderThreeHasNoInvalidElement) {
  ScriptRun run;
  run.run(R"(SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Sphere(2) = {0, 0, 0, 0.7};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.MeshSizeMax = 0.3;
Mesh 3;
SetOrder 3;
)");
  Tally t = tally(run.session.mesh());
  EXPECT_GT(t.types[ElementType::Tet20], 100u);
  EXPECT_GT(t.types[ElementType::Triangle10], 50u);
  EXPECT_EQ(t.invalid, 0u);
  const double exact = 4 * std::numbers::pi / 3 * (1 - 0.7 * 0.7 * 0.7);
  EXPECT_NEAR(t.volume, exact, 2e-3 * exact);
}

TEST(SetOrderStatement, ElementOrderOptionRaisesTheMeshOfMeshN) {
  ScriptRun run;
  run.run(R"(SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 1, 0.5};
Mesh.MeshSizeMax = 0.25;
Mesh.ElementOrder = 2;
Mesh.HighOrderOptimize = 2;
Mesh 3;
)");
  Tally t = tally(run.session.mesh());
  EXPECT_GT(t.types[ElementType::Tet10], 0u);
  EXPECT_EQ(t.types[ElementType::Tet4], 0u);
  EXPECT_EQ(t.invalid, 0u);
  const double exact = std::numbers::pi * 0.25;
  EXPECT_NEAR(t.volume, exact, 1e-3 * exact);
}

TEST(SetOrderStatement, PrismsAboveOrderTwoAreALocatedError) {
  const std::string error = errorOf(R"(Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5};
Point(3) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Extrude{0, 0, 1}{ Surface{1}; Layers{2}; Recombine; }
Mesh 3;
SetOrder 3;
)");
  EXPECT_NE(error.find("prisms of order 3 are not supported"), std::string::npos) << error;
}

TEST(SetOrderStatement, AnOrderOutOfRangeIsRefusedAtItsValue) {
  EXPECT_EQ(firstLineOf("SetOrder 6;"),
            "test.geo:1:10: error: element order 6 is not supported (1 to 4)");
}

}  // namespace
}  // namespace geomesh::testing
