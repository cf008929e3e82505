// Tests of Jacobian bounds, scaled Jacobian and measure of curved elements.
#include "mesh/high_order/jacobian.h"

#include <gtest/gtest.h>

#include <limits>

#include <cmath>
#include <numbers>
#include <vector>

#include "mesh/high_order/reference_element.h"

namespace geomesh {
namespace {

// x = origin + A xi, with det A > 0.
constexpr double kA[3][3] = {{2, 0.3, 0.1}, {0.2, 1.5, 0.4}, {0.1, -0.2, 1.2}};
constexpr Vec3 kOrigin{0.5, -1, 2};

Vec3 affine(const std::array<double, 3>& xi) {
  Vec3 p = kOrigin;
  p.x += kA[0][0] * xi[0] + kA[0][1] * xi[1] + kA[0][2] * xi[2];
  p.y += kA[1][0] * xi[0] + kA[1][1] * xi[1] + kA[1][2] * xi[2];
  p.z += kA[2][0] * xi[0] + kA[2][1] * xi[1] + kA[2][2] * xi[2];
  return p;
}

std::vector<Vec3> straightNodes(ElementType type) {
  std::vector<Vec3> out;
  for (const std::array<double, 3>& xi : referenceElement(type).xi) out.push_back(affine(xi));
  return out;
}

// Reference nodes as points of the plane z = 0 (2D types) or of space.
std::vector<Vec3> referenceNodes(ElementType type) {
  std::vector<Vec3> out;
  for (const std::array<double, 3>& xi : referenceElement(type).xi)
    out.push_back({xi[0], xi[1], xi[2]});
  return out;
}

Vec3 column(int c) { return {kA[0][c], kA[1][c], kA[2][c]}; }

// The determinant of the affine map, as each dimension defines it.
double affineDeterminant(int dim) {
  if (dim == 1) return norm(column(0));
  if (dim == 2) return norm(cross(column(0), column(1)));
  return dot(column(0), cross(column(1), column(2)));
}

double referenceMeasure(ElementFamily f) {
  switch (f) {
    case ElementFamily::Line: return 2;
    case ElementFamily::Triangle: return 0.5;
    case ElementFamily::Quad: return 4;
    case ElementFamily::Tet: return 1.0 / 6;
    case ElementFamily::Hex: return 8;
    case ElementFamily::Prism: return 1;
    case ElementFamily::Pyramid: return 4.0 / 3;
    default: return 0;
  }
}

// The conversion from samples to Bernstein coefficients amplifies rounding with the degree
// (about 1e-4 relative on a hexahedron of order 4), hence the tolerances.
TEST(Jacobian, StraightElementsOfEveryTypeAreValidWithTheirAffineDeterminant) {
  for (const ElementTypeInfo& info : kElementTypes) {
    const ElementType type = info.type;
    if (dimension(type) == 0) continue;
    const std::vector<Vec3> nodes = straightNodes(type);
    const double det = affineDeterminant(dimension(type));
    const JacobianRange r = jacobianRange(type, nodes);
    EXPECT_GT(r.min, 0) << info.name;
    EXPECT_NEAR(r.min, det, 1e-3 * det) << info.name;
    EXPECT_NEAR(r.max, det, 1e-3 * det) << info.name;
    const bool simplex = info.family == ElementFamily::Line ||
                         info.family == ElementFamily::Triangle ||
                         info.family == ElementFamily::Tet;
    EXPECT_NEAR(scaledJacobian(type, nodes), 1, simplex ? 1e-7 : 1e-3) << info.name;
    const double measure = referenceMeasure(info.family) * det;
    EXPECT_NEAR(elementMeasure(type, nodes), measure, 1e-12 * measure) << info.name;
  }
}

TEST(Jacobian, StraightLinearSimplicesAreExact) {
  for (ElementType type : {ElementType::Line2, ElementType::Triangle3, ElementType::Tet4}) {
    const std::vector<Vec3> nodes = straightNodes(type);
    const JacobianRange r = jacobianRange(type, nodes);
    EXPECT_EQ(r.min, r.max) << elementName(type);
    EXPECT_EQ(scaledJacobian(type, nodes), 1) << elementName(type);
  }
}

TEST(Jacobian, StraightVolumesOfEveryOrderEqualTheFirstOrderVolume) {
  for (const ElementTypeInfo& info : kElementTypes) {
    if (dimension(info.family) != 3) continue;
    const std::vector<Vec3> nodes = straightNodes(info.type);
    const ElementType linear = linearType(info.family);
    const std::span<const Vec3> vertices(nodes.data(), vertexCount(linear));
    const double volume = elementMeasure(linear, vertices);
    EXPECT_NEAR(elementMeasure(info.type, nodes), volume, 1e-12 * volume) << info.name;
  }
}

TEST(Jacobian, EdgeNodePulledAcrossTheOppositeVertexIsInvalid) {
  std::vector<Vec3> nodes = referenceNodes(ElementType::Triangle6);
  nodes[3] = {0.1, 1.4, 0};  // the node of edge 0-1, beyond vertex 2
  EXPECT_LT(jacobianRange(ElementType::Triangle6, nodes).min, 0);
  EXPECT_LT(scaledJacobian(ElementType::Triangle6, nodes), 0);
}

// x(u) = (u - 1/2)^3 / 3 + k u, so that dx/du = (u - 1/2)^2 + k.
double cubic(double u, double k) { return (u - 0.5) * (u - 0.5) * (u - 0.5) / 3 + k * u; }

// The nodes of a line or quadrangle of order 3 mapped by (u, v) -> (cubic(u), v).
std::vector<Vec3> cubicNodes(ElementType type, double k) {
  std::vector<Vec3> out;
  for (const std::array<double, 3>& xi : referenceElement(type).xi)
    out.push_back({cubic(xi[0], k), xi[1], 0});
  return out;
}

bool positiveAtEveryNode(ElementType type, const std::vector<Vec3>& nodes) {
  for (const std::array<double, 3>& xi : referenceElement(type).xi)
    if (jacobianDeterminant(type, nodes, xi) <= 0) return false;
  return true;
}

TEST(Jacobian, NegativeBetweenTheNodesAndTheSamplesIsInvalid) {
  // dx/du = (u - 1/2)^2 - 0.005: positive at the nodes (u = +-1, +-1/3) and at the lattice
  // the bound starts from, negative around u = 1/2, which only subdivision reaches.
  for (ElementType type : {ElementType::Line4, ElementType::Quad16}) {
    const std::vector<Vec3> nodes = cubicNodes(type, -0.005);
    ASSERT_TRUE(positiveAtEveryNode(type, nodes)) << elementName(type);
    ASSERT_LT(jacobianDeterminant(type, nodes, {0.5, 0, 0}), 0);
    EXPECT_LE(jacobianRange(type, nodes).min, -0.005 + 1e-9) << elementName(type);
    EXPECT_LT(scaledJacobian(type, nodes), 0) << elementName(type);
  }
}

TEST(Jacobian, PositiveWhereTheFirstCoefficientsAreNotIsValid) {
  // dx/du = (u - 1/2)^2 + 0.01 > 0 has a negative Bernstein coefficient on [-1, 1].
  for (ElementType type : {ElementType::Line4, ElementType::Quad16}) {
    const JacobianRange r = jacobianRange(type, cubicNodes(type, 0.01));
    EXPECT_GT(r.min, 0) << elementName(type);
    EXPECT_LE(r.min, 0.01 + 1e-9) << elementName(type);
    EXPECT_GE(r.max, 1.5 * 1.5 + 0.01 - 1e-9) << elementName(type);
  }
}

TEST(Jacobian, LineNodeRunningBackwardsIsInvalid) {
  const std::vector<Vec3> nodes{{0, 0, 0}, {1, 0, 0}, {1.6, 0, 0}};
  EXPECT_LT(jacobianRange(ElementType::Line3, nodes).min, 0);
  EXPECT_NEAR(elementMeasure(ElementType::Line3, {{{0, 0, 0}, {1, 0, 0}, {0.5, 0.5, 0}}}),
              // arc length of the parabola y = x (1 - x) * 2 from 0 to 1
              (std::sqrt(5.0) + std::asinh(2.0) / 2) / 2, 1e-7);
}

TEST(Jacobian, AreaOfATriangleWithAnEdgeOnACircleArc) {
  // Centre, then two points of the unit circle 60 degrees apart; the node of their edge on
  // the arc. The element is the straight triangle plus a parabolic segment of area
  // (2/3) chord * sagitta.
  const double theta = std::numbers::pi / 3;
  const Vec3 c{0, 0, 0}, a{1, 0, 0}, b{std::cos(theta), std::sin(theta), 0};
  const Vec3 arc{std::cos(theta / 2), std::sin(theta / 2), 0};
  const std::vector<Vec3> nodes{c, a, b, (c + a) / 2, arc, (b + c) / 2};
  const double chord = 2 * std::sin(theta / 2), sagitta = 1 - std::cos(theta / 2);
  const double area = std::sin(theta) / 2 + 2.0 / 3 * chord * sagitta;
  EXPECT_NEAR(elementMeasure(ElementType::Triangle6, nodes), area, 1e-10 * area);
  EXPECT_NEAR(area, theta / 2, 2e-3);  // close to the sector itself
  EXPECT_GT(scaledJacobian(ElementType::Triangle6, nodes), 0.5);
}

TEST(Jacobian, SurfaceElementsInSpaceUseTheirOwnNormal) {
  // The reference triangle turned upside down in space is still valid: n comes from it.
  const std::vector<Vec3> nodes{{0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
  EXPECT_NEAR(scaledJacobian(ElementType::Triangle3, nodes), 1, 1e-14);
  EXPECT_NEAR(elementMeasure(ElementType::Triangle3, nodes), 0.5, 1e-14);
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST(JacobianRangeOfDamagedNodes, ANodeAtNoFinitePlaceMakesTheElementInvalid) {
  std::vector<Vec3> nodes{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 0.5, 0},
                          {0, std::numeric_limits<double>::quiet_NaN(), 0}};
  EXPECT_LT(jacobianRange(ElementType::Triangle6, nodes).min, 0);
  EXPECT_LE(scaledJacobian(ElementType::Triangle6, nodes), 0);
}

}  // namespace
}  // namespace geomesh
