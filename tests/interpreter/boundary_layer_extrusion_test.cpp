// Tests of boundary layers made by extrusion along normals: heights, shared normals, tags.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "api/meshing.h"
#include "tests/interpreter/script_runner.h"

namespace geomesh {
namespace {

using testing::ScriptRun;

const char* kSquare = R"(
Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 1, 0, 0.25}; Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
)";

double det(Vec3 a, Vec3 b, Vec3 c) { return dot(a, cross(b, c)); }

// The Jacobians at the six corners of a prism (bottom a, b, c; top d, e, f over them).
std::vector<double> cornerJacobians(const Mesh& mesh, std::span<const NodeIndex> v) {
  std::vector<double> j;
  for (int i = 0; i < 3; ++i) {
    const int next = (i + 1) % 3, previous = (i + 2) % 3;
    const Vec3 p = mesh.node(v[i]), q = mesh.node(v[i + 3]);
    j.push_back(det(mesh.node(v[next]) - p, mesh.node(v[previous]) - p, q - p));
    j.push_back(det(mesh.node(v[next + 3]) - q, mesh.node(v[previous + 3]) - q, q - p));
  }
  return j;
}

std::vector<NodeIndex> prismsOf(const Mesh& mesh) {
  std::vector<NodeIndex> all;
  for (const auto& [id, em] : mesh.entities())
    if (const ElementBlock* b = em.findBlock(ElementType::Prism6))
      all.insert(all.end(), b->nodes.begin(), b->nodes.end());
  return all;
}

// Every corner of every prism turns the right way.
void expectNoInvertedPrism(const Mesh& mesh, const std::vector<NodeIndex>& prisms) {
  for (std::size_t e = 0; e < prisms.size(); e += 6)
    for (double j : cornerJacobians(mesh, std::span(prisms).subspan(e, 6)))
      EXPECT_GT(j, 0) << "prism " << e / 6;
}

// The heights of the prisms' nodes, those within 1e-12 of each other taken as one.
std::vector<double> levelsOf(const Mesh& mesh, const std::vector<NodeIndex>& prisms) {
  std::set<double> all;
  for (NodeIndex n : prisms) all.insert(mesh.node(n).z);
  std::vector<double> z;
  for (double h : all)
    if (z.empty() || h - z.back() > 1e-12) z.push_back(h);
  return z;
}

TEST(BoundaryLayerExtrusion, FlatWallHeightsFollowTheGeometricLaw) {
  ScriptRun run;
  run.run(std::string(kSquare) + R"(
    h = 0.01; ratio = 1.3; n = 6;
    counts[] = {}; heights[] = {};
    total = 0; step = h;
    For i In {1:n}
      total += step; counts[] += 1; heights[] += total; step *= ratio;
    EndFor
    out[] = Extrude{ Surface{1}; Layers{counts[], heights[]}; Recombine; };
  )");
  api::generate(run.session, 3);
  const Mesh& mesh = run.session.mesh();
  const std::vector<NodeIndex> prisms = prismsOf(mesh);
  ASSERT_FALSE(prisms.empty());
  const std::vector<double> z = levelsOf(mesh, prisms);
  ASSERT_EQ(z.size(), 7u);
  double expected = 0, step = 0.01;
  auto level = z.begin();
  EXPECT_EQ(*level, 0.0);
  for (int i = 1; i <= 6; ++i) {
    expected += step;
    step *= 1.3;
    ++level;
    EXPECT_NEAR(*level, expected, 1e-9) << "layer " << i;
  }
  EXPECT_NEAR(*std::next(z.begin()), 0.01, 1e-15);  // the first cell's height, exactly
  double volume = 0;
  for (std::size_t e = 0; e < prisms.size(); e += 6) {
    const std::span<const NodeIndex> v(prisms.data() + e, 6);
    for (double j : cornerJacobians(mesh, v)) EXPECT_GT(j, 0);
    // Three tetrahedra fill the prism.
    for (int t = 0; t < 3; ++t) {
      const Vec3 a = mesh.node(v[t]);
      volume += det(mesh.node(v[t + 1]) - a, mesh.node(v[t + 2]) - a, mesh.node(v[t + 3]) - a) / 6;
    }
  }
  EXPECT_NEAR(volume, expected, 1e-9);
  const std::size_t triangles = mesh.find({2, 1})->findBlock(ElementType::Triangle3)->size();
  EXPECT_EQ(prisms.size() / 6, 6 * triangles);
}

TEST(BoundaryLayerExtrusion, ReturnsTopVolumeAndSidesWithTheReferenceTags) {
  ScriptRun run;
  const std::string printed = run.run(std::string(kSquare) + R"(
    out[] = Extrude{ Surface{1}; Layers{4, 0.1}; Recombine; };
    Printf("%g %g %g %g %g %g", out[0], out[1], out[2], out[3], out[4], out[5]);
  )");
  EXPECT_EQ(printed, "26 1 13 17 21 25\n");
}

TEST(BoundaryLayerExtrusion, NegativeHeightsGrowTheOtherWay) {
  ScriptRun run;
  run.run(std::string(kSquare) + "Extrude{ Surface{1}; Layers{{2, 2}, {-0.02, -0.05}}; };");
  api::generate(run.session, 3);
  const Mesh& mesh = run.session.mesh();
  double lowest = 0;
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) lowest = std::min(lowest, mesh.node(n).z);
  EXPECT_NEAR(lowest, -0.05, 1e-12);
  EXPECT_GT(mesh.elementCount(3), 0u);
  EXPECT_TRUE(prismsOf(mesh).empty());  // without Recombine: tetrahedra
}

// Two faces at a right angle, extruded by two statements: with one index they share the
// side surface over their common edge and grow along the bisector there; with two, they
// do not.
std::string corner(int secondIndex) {
  return R"(
    Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};
    Point(4) = {0, 1, 0, 0.5}; Point(5) = {0, 0, 1, 0.5}; Point(6) = {1, 0, 1, 0.5};
    Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
    Line(5) = {1, 5}; Line(6) = {5, 6}; Line(7) = {6, 2};
    Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
    Curve Loop(2) = {5, 6, 7, -1}; Plane Surface(2) = {2};
    a[] = Extrude{ Surface{1}; Layers{2, 0.1}; Recombine; };
    b[] = Extrude{ Surface{2}; Layers{2, 0.1}; Using Index[)" +
         std::to_string(secondIndex) + R"(]; Recombine; };
    Printf("%g %g", a[2], b[5]);
  )";
}

TEST(BoundaryLayerExtrusion, LayersOfOneIndexShareTheirSidesAndNormals) {
  ScriptRun run;
  const std::string printed = run.run(corner(0));
  EXPECT_EQ(printed, "16 16\n");  // the side over curve 1, made once
  api::generate(run.session, 3);
  const Mesh& mesh = run.session.mesh();
  // The top of point 2's column, on the bisector of the two faces.
  bool found = false;
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) {
    const Vec3 p = mesh.node(n);
    if (std::abs(p.x - 1) < 1e-12 && std::abs(p.y - 0.1 / std::sqrt(2.0)) < 1e-12 &&
        std::abs(p.z - 0.1 / std::sqrt(2.0)) < 1e-12)
      found = true;
  }
  EXPECT_TRUE(found);
  for (std::size_t e = 0; e < prismsOf(mesh).size(); e += 6) {
    const std::vector<NodeIndex> prisms = prismsOf(mesh);
    for (double j : cornerJacobians(mesh, std::span<const NodeIndex>(prisms.data() + e, 6)))
      EXPECT_GT(j, 0);
  }
}

TEST(BoundaryLayerExtrusion, LayersOfTwoIndicesKeepTheirOwnSides) {
  ScriptRun run;
  const std::string printed = run.run(corner(1));
  EXPECT_NE(printed, "16 16\n");
}

TEST(BoundaryLayerExtrusion, CurvesGrowAlongTheirNormalsInThePlane) {
  ScriptRun run;
  run.run(R"(
    Point(1) = {0, 0, 0, 0.05}; Point(2) = {0.5, 0, 0, 0.05}; Point(3) = {0, 0.5, 0, 0.05};
    Point(4) = {-0.5, 0, 0, 0.05}; Point(5) = {0, -0.5, 0, 0.05};
    Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
    out[] = Extrude{ Curve{1:4}; Layers{{1, 1, 1}, {0.01, 0.03, 0.07}}; Recombine; };
  )");
  api::generate(run.session, 2);
  const Mesh& mesh = run.session.mesh();
  std::set<long long> radii;  // in units of 1e-9
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) {
    const Vec3 p = mesh.node(n);
    if (norm(p) > 0) radii.insert(std::llround(norm(p) * 1e9));
  }
  // A circle's mesh is a polygon: its normals are radial at the nodes, so every node of
  // the layer lies at the circle's radius plus a height of Layers.
  EXPECT_EQ(radii, (std::set<long long>{500000000, 510000000, 530000000, 570000000}));
  EXPECT_GT(mesh.elementCount(2), 0u);
}

// The highest node, and the heights of the layer's top over the line y = 0.5, of a layer of
// height 0.1 grown from the unit square Using View[0].
struct ViewLayer {
  double zmax = 0, xmax = 0;
  std::vector<double> middle;  // the heights of the nodes at y = 0.5
};

ViewLayer layerUsingView(const std::string& view) {
  ScriptRun run;
  run.run(std::string(kSquare) + view +
          "Extrude{ Surface{1}; Layers{1, 0.1}; Using View[0]; Recombine; }\n");
  api::generate(run.session, 3);
  const Mesh& mesh = run.session.mesh();
  ViewLayer out;
  std::set<double> middle;
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) {
    const Vec3 p = mesh.node(n);
    out.zmax = std::max(out.zmax, p.z);
    out.xmax = std::max(out.xmax, p.x);
    if (std::abs(p.y - 0.5) < 1e-9) middle.insert(std::round(p.z * 1e9) / 1e9);
  }
  out.middle.assign(middle.begin(), middle.end());
  return out;
}

TEST(BoundaryLayerExtrusion, AScalarViewScalesTheHeightAtEachNode) {
  // The view is 1 along y = 0 and 3 along y = 1: the layer is 0.1 thick at the bottom, 0.2
  // across the middle and 0.3 at the top.
  const ViewLayer layer =
      layerUsingView("View \"scale\" { SQ(0,0,0, 1,0,0, 1,1,0, 0,1,0){1, 1, 3, 3}; };\n");
  EXPECT_NEAR(layer.zmax, 0.3, 1e-9);
  EXPECT_NEAR(layer.xmax, 1, 1e-12);
  EXPECT_EQ(layer.middle, (std::vector<double>{0, 0.2}));
}

TEST(BoundaryLayerExtrusion, AVectorViewSetsTheDirection) {
  // Every node moves 0.1 along (1, 0, 1): the layer leans over x = 1 and stays 0.1 high.
  const ViewLayer layer = layerUsingView(
      "View \"lean\" { VQ(0,0,0, 1,0,0, 1,1,0, 0,1,0){1,0,1, 1,0,1, 1,0,1, 1,0,1}; };\n");
  EXPECT_NEAR(layer.zmax, 0.1, 1e-12);
  EXPECT_NEAR(layer.xmax, 1.1, 1e-12);
  EXPECT_EQ(layer.middle, (std::vector<double>{0, 0.1}));
}

TEST(BoundaryLayerExtrusion, AMissingViewIsAnErrorNamingItsIndex) {
  ScriptRun run;
  run.run(std::string(kSquare) + "Extrude{ Surface{1}; Layers{1, 0.1}; Using View[4]; }\n");
  try {
    api::generate(run.session, 3);
    FAIL() << "meshing without the view succeeded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("no view at index 4"), std::string::npos) << e.what();
  }
}

TEST(BoundaryLayerExtrusion, LayersGrowingTowardsEachOtherAreMadeThinnerWithAWarning) {
  // A slab 0.1 thick: its floor grows 0.08 up along its normal, its ceiling (the same
  // orientation) 0.08 down against it. Each layer keeps at most 0.45 of the gap.
  ScriptRun run;
  run.run(std::string(kSquare) + R"(
    Translate {0, 0, 0.1} { Duplicata { Surface{1}; } }
    a[] = Extrude { Surface{1}; Layers{{2, 2}, {0.04, 0.08}}; Recombine; };
    b[] = Extrude { Surface{5}; Layers{{2, 2}, {-0.04, -0.08}}; Recombine; };
  )");
  api::generate(run.session, 3);
  const Mesh& mesh = run.session.mesh();
  const std::vector<NodeIndex> prisms = prismsOf(mesh);
  ASSERT_FALSE(prisms.empty());
  expectNoInvertedPrism(mesh, prisms);
  const std::vector<double> z = levelsOf(mesh, prisms);
  ASSERT_EQ(z.size(), 10u);          // 2 + 2 cells on each side, 5 levels
  EXPECT_NEAR(z[2], 0.0225, 1e-12);  // the floor's layer: 0.04 and 0.08 at 0.5625
  EXPECT_NEAR(z[4], 0.045, 1e-12);
  EXPECT_NEAR(z[5], 0.055, 1e-12);   // the ceiling's
  EXPECT_NEAR(z[7], 0.0775, 1e-12);
  bool warned = false;
  for (const std::string& w : run.log.warnings)
    warned = warned || w.find("made thinner than asked") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(BoundaryLayerExtrusion, ALayerGrowsFromTheTopOfAnotherLayer) {
  // Index 1 grows from the top of index 0's layer: it is meshed a round after it.
  ScriptRun run;
  run.run(std::string(kSquare) + R"(
    a[] = Extrude { Surface{1}; Layers{{2}, {0.02}}; Recombine; };
    b[] = Extrude { Surface{a[0]}; Layers{{3}, {0.1}}; Recombine; Using Index[1]; };
  )");
  api::generate(run.session, 3);
  const Mesh& mesh = run.session.mesh();
  const std::vector<NodeIndex> prisms = prismsOf(mesh);
  ASSERT_FALSE(prisms.empty());
  expectNoInvertedPrism(mesh, prisms);
  const std::vector<double> z = levelsOf(mesh, prisms);
  ASSERT_EQ(z.size(), 6u);
  const double expected[] = {0, 0.01, 0.02, 0.02 + 0.1 / 3, 0.02 + 0.2 / 3, 0.12};
  for (std::size_t k = 0; k < z.size(); ++k) EXPECT_NEAR(z[k], expected[k], 1e-9) << k;
  EXPECT_EQ(prisms.size() / 6 % 5, 0u);  // 2 + 3 prisms over each triangle
}

TEST(BoundaryLayerExtrusion, TheOpenCascadeFactoryNamesTheKernelItNeeds) {
  const std::string error = testing::firstLineOf(R"(
    SetFactory("OpenCASCADE");
    Rectangle(1) = {0, 0, 0, 1, 1};
    Extrude{ Surface{1}; Layers{2, 0.1}; }
  )");
  EXPECT_NE(error.find("Built-in"), std::string::npos) << error;
}

TEST(BoundaryLayerExtrusion, LayersAreRequired) {
  const std::string error =
      testing::firstLineOf(std::string(kSquare) + "Extrude{ Surface{1}; Recombine; }");
  EXPECT_NE(error.find("needs Layers"), std::string::npos) << error;
}

}  // namespace
}  // namespace geomesh
