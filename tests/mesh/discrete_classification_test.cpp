// Classification of triangulations: patches by angle and input label, curves and points
// between them, loops that chain and keep their patch on the left, splitting into disks, and
// the repairs of triangle soups.
#include "mesh/discrete/classification.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

namespace geomesh {
namespace {

constexpr double kPi = std::numbers::pi;

// Builds a triangulation from vertices known by integer grid coordinates, each created once.
class GridBuilder {
 public:
  explicit GridBuilder(double step) : step_(step) {}
  std::uint32_t vertex(std::array<int, 3> c) {
    const auto [it, added] = index_.try_emplace(c, static_cast<std::uint32_t>(t_.points.size()));
    if (added) t_.points.push_back({c[0] * step_, c[1] * step_, c[2] * step_});
    return it->second;
  }
  void triangle(std::array<int, 3> a, std::array<int, 3> b, std::array<int, 3> c) {
    t_.triangles.push_back({vertex(a), vertex(b), vertex(c)});
  }
  Triangulation take() { return std::move(t_); }

 private:
  double step_;
  std::map<std::array<int, 3>, std::uint32_t> index_;
  Triangulation t_;
};

// The unit cube, n x n squares per face, each split in two, normals outward.
Triangulation cube(int n) {
  GridBuilder grid(1.0 / n);
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto corner = [&](int di, int dj) {
            std::array<int, 3> c{};
            c[a] = side * n;
            c[(a + 1) % 3] = i + di;
            c[(a + 2) % 3] = j + dj;
            return c;
          };
          if (side == 1) {
            grid.triangle(corner(0, 0), corner(1, 0), corner(1, 1));
            grid.triangle(corner(0, 0), corner(1, 1), corner(0, 1));
          } else {
            grid.triangle(corner(0, 0), corner(1, 1), corner(1, 0));
            grid.triangle(corner(0, 0), corner(0, 1), corner(1, 1));
          }
        }
  return grid.take();
}

// The unit sphere: the cube's grid projected from its centre.
Triangulation sphere(int n) {
  Triangulation t = cube(n);
  for (Vec3& p : t.points) p = normalized(p - Vec3{0.5, 0.5, 0.5});
  return t;
}

// The square [0, 1]^2 in z = 0, n x n squares, normals +z; squares in `holes` left out.
Triangulation plate(int n, std::set<std::pair<int, int>> holes = {}) {
  GridBuilder grid(1.0 / n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (holes.contains({i, j})) continue;
      grid.triangle({i, j, 0}, {i + 1, j, 0}, {i + 1, j + 1, 0});
      grid.triangle({i, j, 0}, {i + 1, j + 1, 0}, {i, j + 1, 0});
    }
  return grid.take();
}

// A tube of radius 1 and height 1 around z, `around` x `rows` quads, normals outward; with
// caps, closed by two fans.
Triangulation cylinder(int around, int rows, bool caps) {
  Triangulation t;
  for (int k = 0; k <= rows; ++k)
    for (int i = 0; i < around; ++i) {
      const double phi = 2 * kPi * i / around;
      t.points.push_back({std::cos(phi), std::sin(phi), double(k) / rows});
    }
  auto ring = [&](int k, int i) { return std::uint32_t(k * around + (i % around)); };
  for (int k = 0; k < rows; ++k)
    for (int i = 0; i < around; ++i) {
      t.triangles.push_back({ring(k, i), ring(k, i + 1), ring(k + 1, i + 1)});
      t.triangles.push_back({ring(k, i), ring(k + 1, i + 1), ring(k + 1, i)});
    }
  if (!caps) return t;
  const auto bottom = std::uint32_t(t.points.size()), top = bottom + 1;
  t.points.push_back({0, 0, 0});
  t.points.push_back({0, 0, 1});
  for (int i = 0; i < around; ++i) {
    t.triangles.push_back({bottom, ring(0, i + 1), ring(0, i)});
    t.triangles.push_back({top, ring(rows, i), ring(rows, i + 1)});
  }
  return t;
}

Triangulation torus(int around, int tube) {
  Triangulation t;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2 * kPi * i / around, v = 2 * kPi * j / tube;
      const double r = 2 + 0.5 * std::cos(v);
      t.points.push_back({r * std::cos(u), r * std::sin(u), 0.5 * std::sin(v)});
    }
  auto at = [&](int i, int j) { return std::uint32_t((i % around) * tube + (j % tube)); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      t.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      t.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return t;
}

std::vector<std::uint32_t> allTriangles(const Triangulation& t) {
  std::vector<std::uint32_t> all(t.triangles.size());
  for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  return all;
}

int labelCount(const std::vector<int>& labels) {
  return labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
}

std::uint32_t startOf(const DiscreteTopology& topology, int c) {
  const auto& v = topology.curves[std::abs(c) - 1].vertices;
  return c > 0 ? v.front() : v.back();
}

// Every loop chains curve end to curve start, is closed, and runs each of its edges the way a
// triangle of its patch does (so the patch lies on its left).
void expectLoopsBoundTheirPatches(const Triangulation& t, const DiscreteTopology& topology) {
  for (std::size_t p = 0; p < topology.patches.size(); ++p) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
    for (std::uint32_t i : topology.patches[p].triangles)
      for (int k = 0; k < 3; ++k)
        directed.emplace(t.triangles[i][k], t.triangles[i][(k + 1) % 3]);
    for (const auto& loop : topology.patches[p].loops) {
      ASSERT_FALSE(loop.empty());
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const int c = loop[k];
        EXPECT_EQ(startOf(topology, -c), startOf(topology, loop[(k + 1) % loop.size()]))
            << "patch " << p << " loop does not chain";
        std::vector<std::uint32_t> v = topology.curves[std::abs(c) - 1].vertices;
        if (c < 0) std::reverse(v.begin(), v.end());
        for (std::size_t i = 1; i < v.size(); ++i)
          EXPECT_TRUE(directed.contains({v[i - 1], v[i]}))
              << "patch " << p << " not on the left of edge " << v[i - 1] << "-" << v[i];
      }
    }
  }
}

TEST(DiscreteClassification, CubeHasSixPatchesTwelveCurvesEightPoints) {
  const Triangulation t = cube(2);
  const std::vector<int> labels = classifyByAngle(t, {}, {});
  EXPECT_EQ(labelCount(labels), 6);
  const DiscreteTopology topology = buildTopology(t, labels, kPi);
  ASSERT_EQ(topology.patches.size(), 6u);
  EXPECT_EQ(topology.curves.size(), 12u);
  ASSERT_EQ(topology.points.size(), 8u);
  EXPECT_TRUE(std::is_sorted(topology.points.begin(), topology.points.end()));
  for (std::uint32_t v : topology.points) {
    const Vec3 p = t.points[v];
    for (double x : {p.x, p.y, p.z}) EXPECT_TRUE(x == 0 || x == 1) << "point off a corner";
  }
  for (const auto& curve : topology.curves) EXPECT_EQ(curve.vertices.size(), 3u);
  for (const auto& patch : topology.patches) {
    EXPECT_EQ(patch.triangles.size(), 8u);
    EXPECT_TRUE(std::is_sorted(patch.triangles.begin(), patch.triangles.end()));
    ASSERT_EQ(patch.loops.size(), 1u);
    EXPECT_EQ(patch.loops[0].size(), 4u);
  }
  expectLoopsBoundTheirPatches(t, topology);
}

TEST(DiscreteClassification, CylinderHasThreePatchesAndTwoClosedCurves) {
  const Triangulation t = cylinder(16, 3, true);
  const std::vector<int> labels = classifyByAngle(t, {}, {});
  EXPECT_EQ(labelCount(labels), 3);
  const DiscreteTopology topology = buildTopology(t, labels, kPi);
  ASSERT_EQ(topology.patches.size(), 3u);
  ASSERT_EQ(topology.curves.size(), 2u);
  EXPECT_EQ(topology.points.size(), 2u);
  for (const auto& curve : topology.curves) {
    EXPECT_EQ(curve.vertices.front(), curve.vertices.back());
    EXPECT_EQ(curve.vertices.size(), 17u);
    EXPECT_EQ(curve.vertices.front(),
              *std::min_element(curve.vertices.begin(), curve.vertices.end()));
  }
  std::vector<std::size_t> loopCounts;
  for (const auto& patch : topology.patches) loopCounts.push_back(patch.loops.size());
  std::sort(loopCounts.begin(), loopCounts.end());
  EXPECT_EQ(loopCounts, (std::vector<std::size_t>{1, 1, 2}));
  expectLoopsBoundTheirPatches(t, topology);
}

TEST(DiscreteClassification, CylinderSideHasTwoBoundaryLoops) {
  const Triangulation t = cylinder(16, 3, false);
  const PatchShape shape = patchShape(t, allTriangles(t));
  EXPECT_EQ(shape.euler, 0);
  EXPECT_EQ(shape.boundaryLoops, 2);
  EXPECT_EQ(shape.genus(), 0);
  EXPECT_FALSE(shape.isDisk());
  const DiscreteTopology topology = buildTopology(t, {}, kPi);
  ASSERT_EQ(topology.patches.size(), 1u);
  EXPECT_EQ(topology.patches[0].loops.size(), 2u);
  EXPECT_EQ(topology.curves.size(), 2u);
  expectLoopsBoundTheirPatches(t, topology);
}

TEST(DiscreteClassification, CurveAngleSplitsAFreeBoundaryAtCorners) {
  const Triangulation t = plate(4);
  const DiscreteTopology split = buildTopology(t, {}, 60 * kPi / 180);
  EXPECT_EQ(split.curves.size(), 4u);
  ASSERT_EQ(split.points.size(), 4u);
  for (std::uint32_t v : split.points) {
    const Vec3 p = t.points[v];
    EXPECT_TRUE((p.x == 0 || p.x == 1) && (p.y == 0 || p.y == 1));
  }
  ASSERT_EQ(split.patches[0].loops.size(), 1u);
  EXPECT_EQ(split.patches[0].loops[0].size(), 4u);
  expectLoopsBoundTheirPatches(t, split);

  const DiscreteTopology whole = buildTopology(t, {}, kPi);
  ASSERT_EQ(whole.curves.size(), 1u);
  EXPECT_EQ(whole.curves[0].vertices.front(), whole.curves[0].vertices.back());
  EXPECT_EQ(whole.points, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(whole.curves[0].vertices.front(), 0u);
  expectLoopsBoundTheirPatches(t, whole);
}

TEST(DiscreteClassification, LongestLoopComesFirst) {
  const Triangulation t = plate(6, {{2, 2}, {2, 3}, {3, 2}, {3, 3}});
  const DiscreteTopology topology = buildTopology(t, {}, kPi);
  ASSERT_EQ(topology.patches.size(), 1u);
  const auto& loops = topology.patches[0].loops;
  ASSERT_EQ(loops.size(), 2u);
  ASSERT_EQ(loops[0].size(), 1u);
  const auto& outer = topology.curves[std::abs(loops[0][0]) - 1].vertices;
  EXPECT_EQ(outer.size(), 25u);  // 24 edges around the outside, closed
  expectLoopsBoundTheirPatches(t, topology);
}

TEST(DiscreteClassification, IncludeBoundaryKeepsInputLabelsApart) {
  const Triangulation t = plate(4);
  std::vector<int> input(t.triangles.size());
  for (std::uint32_t i = 0; i < input.size(); ++i)
    input[i] = t.points[t.triangles[i][0]].x < 0.5 ? 0 : 1;
  ClassifyOptions options;
  const std::vector<int> apart = classifyByAngle(t, input, options);
  EXPECT_EQ(labelCount(apart), 2);
  for (std::uint32_t i = 0; i < input.size(); ++i) EXPECT_EQ(apart[i], input[i]);
  options.includeBoundary = false;
  EXPECT_EQ(labelCount(classifyByAngle(t, input, options)), 1);

  // The interface ends where three feature edges meet; each half keeps its free boundary.
  const DiscreteTopology topology = buildTopology(t, apart, kPi);
  EXPECT_EQ(topology.patches.size(), 2u);
  EXPECT_EQ(topology.curves.size(), 3u);
  EXPECT_EQ(topology.points.size(), 2u);
  for (const auto& patch : topology.patches) EXPECT_EQ(patch.loops.at(0).size(), 2u);
  expectLoopsBoundTheirPatches(t, topology);
}

// A fin standing on a plate along one inner edge a-b: at a and b the edge between the two
// patches meets the fin's free boundary (along the fin only), so the curves break there
// although only two feature edges meet.
TEST(DiscreteClassification, CurveBreaksWhereThePatchesAlongItChange) {
  Triangulation t = plate(3);
  auto vertexAt = [&](Vec3 p) {
    return std::uint32_t(std::find(t.points.begin(), t.points.end(), p) - t.points.begin());
  };
  const std::uint32_t a = vertexAt({1 / 3.0, 1 / 3.0, 0}), b = vertexAt({2 / 3.0, 1 / 3.0, 0});
  ASSERT_LT(std::max(a, b), t.points.size());
  const auto apex = std::uint32_t(t.points.size());
  t.points.push_back({0.5, 1 / 3.0, 0.5});
  t.triangles.push_back({a, b, apex});
  const DiscreteTopology topology = buildTopology(t, {}, kPi);
  EXPECT_EQ(topology.patches.size(), 2u);
  std::vector<std::uint32_t> points{0, a, b};
  std::sort(points.begin(), points.end());
  EXPECT_EQ(topology.points, points);
  EXPECT_EQ(topology.curves.size(), 3u);
  ASSERT_EQ(topology.patches[1].loops.size(), 1u);
  EXPECT_EQ(topology.patches[1].loops[0].size(), 2u);
  expectLoopsBoundTheirPatches(t, topology);
}

TEST(DiscreteClassification, SplitPatchGivesTwoConnectedHalvesOfSimilarSize) {
  const Triangulation t = sphere(8);
  const auto halves = splitPatch(t, allTriangles(t));
  const double a = double(halves[0].size()), b = double(halves[1].size());
  EXPECT_EQ(a + b, double(t.triangles.size()));
  EXPECT_LT(std::abs(a - b), 0.2 * std::max(a, b));
  std::vector<int> half(t.triangles.size(), -1);
  for (int h = 0; h < 2; ++h) {
    EXPECT_TRUE(std::is_sorted(halves[h].begin(), halves[h].end()));
    for (std::uint32_t i : halves[h]) half[i] = h;
  }
  EXPECT_EQ(std::count(half.begin(), half.end(), -1), 0);
  // Connected halves: one patch each.
  EXPECT_EQ(buildTopology(t, half, kPi).patches.size(), 2u);
}

TEST(DiscreteClassification, ForReparametrizationGivesDisks) {
  const Triangulation t = sphere(8);
  EXPECT_EQ(labelCount(classifyByAngle(t, {}, {})), 1);
  ClassifyOptions options;
  options.forReparametrization = true;
  const std::vector<int> labels = classifyByAngle(t, {}, options);
  const int count = labelCount(labels);
  EXPECT_GE(count, 2);
  std::vector<std::vector<std::uint32_t>> regions(count);
  for (std::uint32_t i = 0; i < labels.size(); ++i) regions[labels[i]].push_back(i);
  for (const auto& region : regions) {
    const PatchShape shape = patchShape(t, region);
    EXPECT_EQ(shape.genus(), 0);
    EXPECT_EQ(shape.boundaryLoops, 1);
  }
  const DiscreteTopology topology = buildTopology(t, labels, kPi);
  EXPECT_EQ(topology.patches.size(), std::size_t(count));
  for (const auto& patch : topology.patches) EXPECT_EQ(patch.loops.size(), 1u);
  expectLoopsBoundTheirPatches(t, topology);
}

TEST(DiscreteClassification, TorusHasGenusOne) {
  const Triangulation t = torus(24, 12);
  const PatchShape shape = patchShape(t, allTriangles(t));
  EXPECT_EQ(shape.euler, 0);
  EXPECT_EQ(shape.boundaryLoops, 0);
  EXPECT_EQ(shape.genus(), 1);

  ClassifyOptions options;
  options.angle = kPi;
  options.forReparametrization = true;
  const std::vector<int> labels = classifyByAngle(t, {}, options);
  std::vector<std::vector<std::uint32_t>> regions(labelCount(labels));
  for (std::uint32_t i = 0; i < labels.size(); ++i) regions[labels[i]].push_back(i);
  for (const auto& region : regions) EXPECT_TRUE(patchShape(t, region).isDisk());
}

TEST(DiscreteClassification, MergeDuplicateVerticesWeldsATriangleSoup) {
  const Triangulation welded = cube(2);
  Triangulation soup;
  for (const TriangleVertices& triangle : welded.triangles) {
    TriangleVertices own;
    for (int k = 0; k < 3; ++k) {
      own[k] = std::uint32_t(soup.points.size());
      const double jitter = 1e-9 * double(soup.points.size() % 7);
      soup.points.push_back(welded.points[triangle[k]] + Vec3{jitter, -jitter, jitter});
    }
    soup.triangles.push_back(own);
  }
  soup.triangles.push_back(soup.triangles[5]);                        // duplicated
  soup.triangles.push_back({soup.triangles[6][2], soup.triangles[6][1], soup.triangles[6][0]});
  const auto nearCorner = std::uint32_t(soup.points.size());  // welds onto triangle 7's corner
  soup.points.push_back(soup.points[soup.triangles[7][0]] + Vec3{1e-8, 0, 0});
  soup.triangles.push_back({soup.triangles[7][0], soup.triangles[7][1], nearCorner});
  const std::size_t expectedMerged = soup.points.size() - welded.points.size();
  EXPECT_EQ(mergeDuplicateVertices(soup, 1e-6), expectedMerged);
  EXPECT_EQ(soup.points.size(), welded.points.size());
  EXPECT_EQ(soup.triangles.size(), welded.triangles.size());

  const DiscreteTopology topology = buildTopology(soup, classifyByAngle(soup, {}, {}), kPi);
  EXPECT_EQ(topology.patches.size(), 6u);
  EXPECT_EQ(topology.curves.size(), 12u);
  EXPECT_EQ(topology.points.size(), 8u);
}

TEST(DiscreteClassification, MergeDuplicateVerticesExactWithZeroTolerance) {
  Triangulation t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-12}};
  t.triangles = {{0, 1, 2}, {3, 4, 5}};
  EXPECT_EQ(mergeDuplicateVertices(t, 0), 1u);
  EXPECT_EQ(t.points.size(), 5u);
  EXPECT_EQ(t.triangles[1][0], 1u);
}

TEST(DiscreteClassification, OrientConsistentlyRepairsFlippedTriangles) {
  Triangulation t = cube(3);
  std::size_t flipped = 0;
  for (std::size_t i = 1; i < t.triangles.size(); i += 3, ++flipped)
    std::swap(t.triangles[i][0], t.triangles[i][1]);
  EXPECT_EQ(orientConsistently(t), flipped);
  for (std::uint32_t i = 0; i < t.triangles.size(); ++i) {
    const auto& v = t.triangles[i];
    const Vec3 centroid = (t.points[v[0]] + t.points[v[1]] + t.points[v[2]]) / 3.0;
    EXPECT_GT(dot(triangleNormal(t, i), centroid - Vec3{0.5, 0.5, 0.5}), 0) << i;
  }
  EXPECT_EQ(orientConsistently(t), 0u);
}

TEST(DiscreteClassification, NonManifoldEdgeYieldsCurvesAlongIt) {
  Triangulation t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -0.5, 0.8}, {0.5, -0.5, -0.8}};
  t.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const std::vector<int> labels = classifyByAngle(t, {}, {});
  EXPECT_EQ(labelCount(labels), 3);
  const DiscreteTopology topology = buildTopology(t, std::vector<int>(3, 0), kPi);
  EXPECT_EQ(topology.patches.size(), 3u);
  EXPECT_EQ(topology.curves.size(), 4u);
  EXPECT_EQ(topology.points, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_TRUE(std::any_of(topology.curves.begin(), topology.curves.end(), [](const auto& c) {
    return c.vertices == std::vector<std::uint32_t>{0, 1};
  }));
  for (const auto& patch : topology.patches) {
    ASSERT_EQ(patch.loops.size(), 1u);
    EXPECT_EQ(patch.loops[0].size(), 2u);
  }
  expectLoopsBoundTheirPatches(t, topology);
  EXPECT_EQ(orientConsistently(t), 0u);  // nothing joins across the non-manifold edge
}

TEST(DiscreteClassification, LargeTriangulationClassifiesQuickly) {
  const Triangulation t = torus(600, 250);  // 300k triangles
  const auto start = std::chrono::steady_clock::now();
  const std::vector<int> labels = classifyByAngle(t, {}, {});
  const DiscreteTopology topology = buildTopology(t, labels, kPi);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(topology.patches.size(), 1u);
  EXPECT_TRUE(topology.curves.empty());
  EXPECT_LT(seconds, 5.0);
}

}  // namespace
}  // namespace geomesh
