// Tests of gamma and SICN on equilateral, flat and degenerate elements, and mesh statistics.
#include "mesh/core/quality.h"

#include <gtest/gtest.h>

#include <cmath>

namespace geomesh {
namespace {

const double kSqrt3 = std::sqrt(3.0);

TEST(Quality, EquilateralTriangleScoresOne) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.5, kSqrt3 / 2, 0};
  EXPECT_NEAR(triangleGamma(a, b, c), 1, 1e-12);
  EXPECT_NEAR(triangleSicn(a, b, c), 1, 1e-12);
  EXPECT_NEAR(triangleSicn(a, b, c, {0, 0, 1}), 1, 1e-12);
  EXPECT_NEAR(triangleSicn(a, c, b, {0, 0, 1}), -1, 1e-12);  // clockwise seen from +z
}

TEST(Quality, RightIsoscelesTriangle) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  // gamma = 2 r / R = 2 (1 - 1/sqrt2) / (sqrt2 / 2) = 2 (sqrt2 - 1)
  EXPECT_NEAR(triangleGamma(a, b, c), 2 * (std::sqrt(2.0) - 1), 1e-12);
  // SICN = 4 sqrt3 area / sum of squared edges = 2 sqrt3 / 4
  EXPECT_NEAR(triangleSicn(a, b, c), kSqrt3 / 2, 1e-12);
}

TEST(Quality, FlatTriangleScoresZero) {
  EXPECT_EQ(triangleGamma({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), 0);
  EXPECT_EQ(triangleSicn({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), 0);
  EXPECT_EQ(triangleGamma({0, 0, 0}, {0, 0, 0}, {0, 0, 0}), 0);
}

TEST(Quality, RegularTetrahedronScoresOne) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.5, kSqrt3 / 2, 0}, d{0.5, kSqrt3 / 6, std::sqrt(2.0 / 3)};
  EXPECT_NEAR(tetGamma(a, b, c, d), 1, 1e-12);
  EXPECT_NEAR(tetSicn(a, b, c, d), 1, 1e-12);
  EXPECT_NEAR(tetSicn(b, a, c, d), -1, 1e-12);  // inverted
  // Scaling and moving do not matter.
  const Vec3 s{3, -2, 7};
  EXPECT_NEAR(tetGamma(s + 5 * a, s + 5 * b, s + 5 * c, s + 5 * d), 1, 1e-12);
}

TEST(Quality, DegenerateTetrahedra) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  EXPECT_EQ(tetSicn(a, b, c, {0.3, 0.3, 0}), 0);  // flat
  EXPECT_EQ(tetGamma(a, b, c, {0.3, 0.3, 0}), 0);
  const double corner = tetGamma(a, b, c, {0, 0, 1});  // trirectangular corner
  EXPECT_GT(corner, 0.5);
  EXPECT_LT(corner, 0.8);
  EXPECT_LT(tetSicn(a, b, c, {0.3, 0.3, 1e-3}), 0.01);  // sliver-like
  EXPECT_GT(tetSicn(a, b, c, {0.3, 0.3, 1e-3}), 0);
}

TEST(Quality, CornerScaledJacobianOfIdealElementsIsOne) {
  const Vec3 tet[] = {{0, 0, 0}, {1, 0, 0}, {0.5, kSqrt3 / 2, 0}, {0.5, kSqrt3 / 6, std::sqrt(2.0 / 3)}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Tet4, tet), 1, 1e-12);
  const Vec3 cube[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                       {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Hex8, cube), 1, 1e-12);
  // A right prism stays ideal however thin: the measure sees angles, not aspect ratios.
  const Vec3 prism[] = {{0, 0, 0}, {1, 0, 0}, {0.5, kSqrt3 / 2, 0},
                        {0, 0, 1e-3}, {1, 0, 1e-3}, {0.5, kSqrt3 / 2, 1e-3}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Prism6, prism), 1, 1e-12);
  const Vec3 square[] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Quad4, square), 1, 1e-12);
  const Vec3 triangle[] = {{0, 0, 0}, {1, 0, 0}, {0.5, kSqrt3 / 2, 0}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Triangle3, triangle), 1, 1e-12);
  const double h = 1 / std::sqrt(2.0);  // equilateral side faces
  const Vec3 pyramid[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, h}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Pyramid5, pyramid), 1, 1e-12);
}

TEST(Quality, CornerScaledJacobianOfDistortedAndInvertedElements) {
  // The top of the cube sheared by half an edge: every corner sees the slanted edge.
  const Vec3 sheared[] = {{0, 0, 0},   {1, 0, 0},   {1, 1, 0},   {0, 1, 0},
                          {0.5, 0, 1}, {1.5, 0, 1}, {1.5, 1, 1}, {0.5, 1, 1}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Hex8, sheared), 2 / std::sqrt(5.0), 1e-12);
  // Right isosceles triangle: the worst corner is 45 degrees, sin 45 / sin 60.
  const Vec3 right[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Triangle3, right),
              std::sqrt(2.0) / 2 / (kSqrt3 / 2), 1e-12);
  const Vec3 inverted[] = {{1, 0, 0}, {0, 0, 0}, {0.5, kSqrt3 / 2, 0},
                           {0.5, kSqrt3 / 6, std::sqrt(2.0 / 3)}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Tet4, inverted), -1, 1e-12);
  // A dart: the corner at (0.5, 0.3) is reflex.
  const Vec3 dart[] = {{0, 0, 0}, {0.5, 0.3, 0}, {1, 0, 0}, {0.5, 1, 0}};
  EXPECT_LT(cornerScaledJacobian(ElementType::Quad4, dart), 0);
  const Vec3 below[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, -0.7}};
  EXPECT_LT(cornerScaledJacobian(ElementType::Pyramid5, below), 0);
  // Nodes past the vertices (second order) are ignored.
  const Vec3 tet10[] = {{0, 0, 0}, {1, 0, 0}, {0.5, kSqrt3 / 2, 0},
                        {0.5, kSqrt3 / 6, std::sqrt(2.0 / 3)}, {9, 9, 9}, {9, 9, 9},
                        {9, 9, 9}, {9, 9, 9}, {9, 9, 9}, {9, 9, 9}};
  EXPECT_NEAR(cornerScaledJacobian(ElementType::Tet10, tet10), 1, 1e-12);
}

TEST(Quality, MeshStatistics) {
  Mesh mesh;
  mesh.reserveNodes(4);
  const NodeIndex a = mesh.addNode({0, 0, 0}), b = mesh.addNode({1, 0, 0}),
                  c = mesh.addNode({0.5, kSqrt3 / 2, 0}), d = mesh.addNode({0, 1, 0});
  ElementBlock& triangles = mesh.entity({2, 1}).block(ElementType::Triangle3);
  triangles.nodes = {a, b, c, a, b, d};
  const QualityStats gamma = meshQuality(mesh, 2, QualityMeasure::Gamma);
  EXPECT_EQ(gamma.count, 2u);
  EXPECT_NEAR(gamma.min, 2 * (std::sqrt(2.0) - 1), 1e-12);
  EXPECT_NEAR(gamma.mean, 0.5 * (1 + 2 * (std::sqrt(2.0) - 1)), 1e-12);
  EXPECT_EQ(meshQuality(mesh, 3, QualityMeasure::Sicn).count, 0u);
}

}  // namespace
}  // namespace geomesh
