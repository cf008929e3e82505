// Tests of the Lagrange shape functions of every element type: Kronecker property at the
// reference nodes, partition of unity, exact affine maps, gradients, serendipity spaces.
#include "mesh/high_order/shape_functions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <thread>

#include "mesh/high_order/reference_element.h"

namespace geomesh {
namespace {

std::vector<ElementType> allTypes() {
  std::vector<ElementType> out;
  for (const ElementTypeInfo& info : kElementTypes) out.push_back(info.type);
  return out;
}

// A point inside the reference element of any family.
std::array<double, 3> insidePoint(ElementFamily f) {
  switch (f) {
    case ElementFamily::Triangle: return {0.21, 0.33, 0};
    case ElementFamily::Tet: return {0.17, 0.22, 0.31};
    case ElementFamily::Prism: return {0.21, 0.33, -0.37};
    case ElementFamily::Pyramid: return {0.12, -0.27, 0.41};
    case ElementFamily::Line: return {0.37, 0, 0};
    case ElementFamily::Quad: return {0.37, -0.61, 0};
    default: return {0.37, -0.61, 0.23};
  }
}

TEST(ShapeFunctions, EachIsOneAtItsNodeAndZeroAtTheOthers) {
  for (ElementType type : allTypes()) {
    const ShapeFunctions& shape = shapeFunctions(type);
    const ReferenceElement& ref = referenceElement(type);
    ASSERT_EQ(shape.size(), nodeCount(type)) << elementName(type);
    std::vector<double> v(shape.size());
    for (std::size_t k = 0; k < ref.xi.size(); ++k) {
      shape.values(ref.xi[k], v);
      for (std::size_t i = 0; i < v.size(); ++i)
        ASSERT_NEAR(v[i], i == k ? 1 : 0, 1e-10) << elementName(type) << " node " << k;
    }
  }
}

TEST(ShapeFunctions, AddUpToOneAndReproduceTheReferenceCoordinates) {
  for (ElementType type : allTypes()) {
    const ShapeFunctions& shape = shapeFunctions(type);
    const ReferenceElement& ref = referenceElement(type);
    const std::array<double, 3> xi = insidePoint(family(type));
    std::vector<double> v(shape.size());
    std::vector<std::array<double, 3>> g(shape.size());
    shape.values(xi, v);
    shape.gradients(xi, g);
    std::array<double, 3> sum{}, at{};
    std::array<std::array<double, 3>, 3> jacobian{};
    for (int i = 0; i < shape.size(); ++i)
      for (int d = 0; d < 3; ++d) {
        sum[d] += g[i][d];
        at[d] += v[i] * ref.xi[i][d];
        for (int e = 0; e < 3; ++e) jacobian[d][e] += ref.xi[i][d] * g[i][e];
      }
    double total = 0;
    for (double x : v) total += x;
    EXPECT_NEAR(total, 1, 1e-11) << elementName(type);
    for (int d = 0; d < dimension(type); ++d) {
      EXPECT_NEAR(sum[d], 0, 1e-10) << elementName(type);
      EXPECT_NEAR(at[d], xi[d], 1e-11) << elementName(type);
      for (int e = 0; e < dimension(type); ++e)
        EXPECT_NEAR(jacobian[d][e], d == e ? 1 : 0, 1e-10) << elementName(type);
    }
  }
}

TEST(ShapeFunctions, GradientsMatchFiniteDifferences) {
  const double h = 1e-6;
  for (ElementType type : allTypes()) {
    const ShapeFunctions& shape = shapeFunctions(type);
    const std::array<double, 3> xi = insidePoint(family(type));
    const auto n = static_cast<std::size_t>(shape.size());
    std::vector<std::array<double, 3>> g(n);
    shape.gradients(xi, g);
    std::vector<double> plus(n), minus(n);
    for (int d = 0; d < dimension(type); ++d) {
      std::array<double, 3> a = xi, b = xi;
      a[d] += h, b[d] -= h;
      shape.values(a, plus);
      shape.values(b, minus);
      for (std::size_t i = 0; i < n; ++i)
        ASSERT_NEAR(g[i][d], (plus[i] - minus[i]) / (2 * h), 1e-6) << elementName(type);
    }
  }
}

TEST(ShapeFunctions, Quad8SpansTheQuadraticSerendipitySpace) {
  const std::span<const Monomial> m = shapeFunctions(ElementType::Quad8).monomials();
  const std::set<Monomial> got(m.begin(), m.end());
  const std::set<Monomial> want{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0},
                                {1, 1, 0}, {0, 2, 0}, {2, 1, 0}, {1, 2, 0}};
  EXPECT_EQ(got, want);
}

TEST(ShapeFunctions, SerendipitySpacesHoldTheLinearOnesAndNoFaceBubble) {
  for (ElementType type : allTypes()) {
    if (!isSerendipity(type)) continue;
    const std::span<const Monomial> m = shapeFunctions(type).monomials();
    const std::set<Monomial> got(m.begin(), m.end());
    EXPECT_EQ(got.size(), m.size()) << elementName(type);
    for (int d = 0; d < dimension(type); ++d) {
      Monomial e{};
      e[d] = 1;
      EXPECT_TRUE(got.count(e)) << elementName(type);
    }
    if (family(type) != ElementFamily::Quad && family(type) != ElementFamily::Hex) continue;
    for (const Monomial& e : m) {  // only one variable above degree 1
      EXPECT_LE(std::count_if(e.begin(), e.end(), [](int a) { return a >= 2; }), 1)
          << elementName(type);
    }
  }
}

TEST(ShapeFunctions, BuildsOnceFromSeveralThreads) {
  std::vector<const ShapeFunctions*> seen(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t)
    threads.emplace_back([&, t] { seen[t] = &shapeFunctions(ElementType::Hex125); });
  for (std::thread& t : threads) t.join();
  for (const ShapeFunctions* s : seen) EXPECT_EQ(s, seen[0]);
}

}  // namespace
}  // namespace geomesh
