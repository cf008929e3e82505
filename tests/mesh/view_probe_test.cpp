// ViewProbe: point location and exact interpolation of linear fields in every element shape.
#include "mesh/views/view_probe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

namespace geomesh::post {
namespace {

// An affine field and an affine map of the reference corners, so that every shape (pyramids
// and bilinear quadrangles included) reproduces the field exactly.
double linearField(Vec3 p) {
  return 1.5 + 2 * p.x - 3 * p.y + 0.5 * p.z;
}

Vec3 mapped(Vec3 r) {
  return {0.3 + 1.2 * r.x + 0.2 * r.y + 0.1 * r.z, -0.4 + 0.1 * r.x + 0.9 * r.y - 0.2 * r.z,
          0.7 + 0.05 * r.x + 0.3 * r.y + 1.1 * r.z};
}

struct ShapeCase {
  ElementShape shape;
  std::vector<Vec3> corners;  // reference corners, MSH order
  Vec3 inside;                // a reference point inside
  Vec3 outside;               // a reference point outside
};

std::vector<ShapeCase> shapeCases() {
  return {
      {ElementShape::Line, {{0, 0, 0}, {1, 0, 0}}, {0.3, 0, 0}, {1.2, 0, 0}},
      {ElementShape::Triangle, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0.2, 0.3, 0}, {0.6, 0.6, 0}},
      {ElementShape::Quadrangle,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
       {0.7, 0.2, 0},
       {1.1, 0.5, 0}},
      {ElementShape::Tetrahedron,
       {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
       {0.1, 0.2, 0.3},
       {0.4, 0.4, 0.4}},
      {ElementShape::Hexahedron,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
       {0.2, 0.7, 0.4},
       {0.5, 0.5, 1.3}},
      {ElementShape::Prism,
       {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
       {0.2, 0.3, 0.8},
       {0.7, 0.7, 0.5}},
      {ElementShape::Pyramid,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}},
       {0.4, 0.6, 0.5},
       {0.1, 0.1, 0.8}},
  };
}

// A view with one element of the case's shape: scalar values of linearField, or a vector
// (f, 2f, -f), or a tensor of entries f + i.
View oneElementView(const ShapeCase& c, FieldKind kind) {
  View view;
  ElementList& l = view.list(c.shape, kind);
  for (Vec3 r : c.corners) {
    const Vec3 x = mapped(r);
    l.coordinates.insert(l.coordinates.end(), {x.x, x.y, x.z});
    const double f = linearField(x);
    if (kind == FieldKind::Scalar) l.values.push_back(f);
    if (kind == FieldKind::Vector) l.values.insert(l.values.end(), {f, 2 * f, -f});
    if (kind == FieldKind::Tensor)
      for (int i = 0; i < 9; ++i) l.values.push_back(f + i);
  }
  return view;
}

TEST(ViewProbe, RecoversLinearFieldsExactlyInEveryShape) {
  for (const ShapeCase& c : shapeCases()) {
    const View view = oneElementView(c, FieldKind::Scalar);
    const ViewProbe probe(view);
    const Vec3 p = mapped(c.inside);
    const std::optional<double> v = probe.scalar(p);
    ASSERT_TRUE(v) << shapeLetter(c.shape);
    EXPECT_NEAR(*v, linearField(p), 1e-12) << shapeLetter(c.shape);
    // Every corner is found and gives its value.
    for (Vec3 r : c.corners) {
      const std::optional<double> at = probe.scalar(mapped(r));
      ASSERT_TRUE(at) << shapeLetter(c.shape);
      EXPECT_NEAR(*at, linearField(mapped(r)), 1e-12) << shapeLetter(c.shape);
    }
    EXPECT_FALSE(probe.scalar(mapped(c.outside))) << shapeLetter(c.shape);
    EXPECT_FALSE(probe.scalar({50, 50, 50})) << shapeLetter(c.shape);
  }
}

TEST(ViewProbe, InterpolatesEveryComponent) {
  for (const ShapeCase& c : shapeCases()) {
    const View vectors = oneElementView(c, FieldKind::Vector);
    const Vec3 p = mapped(c.inside);
    const double f = linearField(p);
    int count = 0;
    const auto v = ViewProbe(vectors).components(p, &count);
    ASSERT_TRUE(v);
    EXPECT_EQ(count, 3);
    EXPECT_NEAR((*v)[0], f, 1e-12);
    EXPECT_NEAR((*v)[1], 2 * f, 1e-12);
    EXPECT_NEAR((*v)[2], -f, 1e-12);
    EXPECT_NEAR(*ViewProbe(vectors).scalar(p), std::sqrt(6.0) * std::abs(f), 1e-11);

    const View tensors = oneElementView(c, FieldKind::Tensor);
    const auto t = ViewProbe(tensors).tensor(p);
    ASSERT_TRUE(t);
    // Rows (f, f+1, f+2), (f+3, f+4, f+5), (f+6, f+7, f+8), symmetrised.
    const double expected[6] = {f, f + 2, f + 4, f + 4, f + 6, f + 8};
    for (int k = 0; k < 6; ++k) EXPECT_NEAR((*t)[k], expected[k], 1e-11) << k;
    EXPECT_FALSE(ViewProbe(vectors).tensor(p));
  }
}

// Distorted (non-affine) quadrangle and hexahedron: the point mapped from reference
// coordinates (u, v, w) is found there and gets the (bi/tri)linear blend of the corner values.
TEST(ViewProbe, InvertsBilinearAndTrilinearMaps) {
  const double u = 0.3, v = 0.6, w = 0.2;
  const double quadWeights[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
  const Vec3 quad[4] = {{0, 0, 0}, {2, 0, 0}, {1.5, 1.2, 0}, {0.2, 0.8, 0}};
  const double quadValues[4] = {1, -2, 5, 3};
  View q;
  ElementList& lq = q.list(ElementShape::Quadrangle, FieldKind::Scalar);
  Vec3 p{};
  double expected = 0;
  for (int i = 0; i < 4; ++i) {
    lq.coordinates.insert(lq.coordinates.end(), {quad[i].x, quad[i].y, quad[i].z});
    lq.values.push_back(quadValues[i]);
    p += quadWeights[i] * quad[i];
    expected += quadWeights[i] * quadValues[i];
  }
  ASSERT_TRUE(ViewProbe(q).scalar(p));
  EXPECT_NEAR(*ViewProbe(q).scalar(p), expected, 1e-12);

  View h;
  ElementList& lh = h.list(ElementShape::Hexahedron, FieldKind::Scalar);
  p = {};
  expected = 0;
  for (int i = 0; i < 8; ++i) {
    const double weight = quadWeights[i % 4] * (i < 4 ? 1 - w : w);
    const Vec3 x = quad[i % 4] + Vec3{0.1 * (i % 3), 0.05 * i, i < 4 ? 0.0 : 1.0 + 0.1 * i};
    lh.coordinates.insert(lh.coordinates.end(), {x.x, x.y, x.z});
    lh.values.push_back(i * i - 3.0);
    p += weight * x;
    expected += weight * (i * i - 3.0);
  }
  ASSERT_TRUE(ViewProbe(h).scalar(p));
  EXPECT_NEAR(*ViewProbe(h).scalar(p), expected, 1e-12);
}

TEST(ViewProbe, SecondOrderListsUseTheirCorners) {
  View view;
  ElementList& l = view.list(ElementShape::Triangle, FieldKind::Scalar, 2);
  l.nodesPerElement = 6;
  const Vec3 nodes[6] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (Vec3 x : nodes) {
    l.coordinates.insert(l.coordinates.end(), {x.x, x.y, x.z});
    l.values.push_back(x.x * x.x + 1);  // quadratic; the corners give the linear 1 + 2x
  }
  const auto v = ViewProbe(view).scalar({0.5, 0.5, 0});
  ASSERT_TRUE(v);
  EXPECT_NEAR(*v, 2.0, 1e-12);
}

TEST(ViewProbe, FindsTrianglesForPointsSlightlyOffTheirPlane) {
  View view;
  ElementList& l = view.list(ElementShape::Triangle, FieldKind::Scalar);
  l.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  l.values = {0, 1, 2};
  const ViewProbe probe(view);
  const auto v = probe.scalar({0.25, 0.25, 1e-4});
  ASSERT_TRUE(v);
  EXPECT_NEAR(*v, 0.75, 1e-12);
  EXPECT_FALSE(probe.scalar({0.25, 0.25, 0.5}));
  EXPECT_FALSE(probe.scalar({0.6, 0.6, 0}));
  // Within the tolerance (1e-6 of the extent) of an edge, and beyond it.
  EXPECT_TRUE(probe.scalar({0.5 + 1e-8, 0.5, 0}));
  EXPECT_FALSE(probe.scalar({0.5 + 1e-4, 0.5, 0}));
}

// A unit square in n x n cells, two triangles each, values of an affine field.
View squareView(int n, bool withLines) {
  View view;
  ElementList& t = view.list(ElementShape::Triangle, FieldKind::Scalar);
  const double h = 1.0 / n;
  auto add = [&](ElementList& l, std::initializer_list<Vec3> corners, double shift) {
    for (Vec3 x : corners) {
      l.coordinates.insert(l.coordinates.end(), {x.x, x.y, x.z});
      l.values.push_back(linearField(x) + shift);
    }
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 a{i * h, j * h, 0}, b{(i + 1) * h, j * h, 0}, c{(i + 1) * h, (j + 1) * h, 0},
          d{i * h, (j + 1) * h, 0};
      add(t, {a, b, c}, 0);
      add(t, {a, c, d}, 0);
    }
  if (withLines) add(view.list(ElementShape::Line, FieldKind::Scalar), {{0, 0, 0}, {1, 0, 0}}, 100);
  return view;
}

TEST(ViewProbe, LocatesPointsInManyElements) {
  const View view = squareView(40, false);
  const ViewProbe probe(view);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 p{std::fmod(k * 0.6180339887, 1.0), std::fmod(k * 0.7548776662, 1.0), 0};
    const auto v = probe.scalar(p);
    ASSERT_TRUE(v) << p.x << " " << p.y;
    EXPECT_NEAR(*v, linearField(p), 1e-12);
  }
  EXPECT_FALSE(probe.scalar({1.01, 0.5, 0}));
  EXPECT_FALSE(probe.scalar({-0.01, 0.5, 0}));
}

TEST(ViewProbe, PrefersTheHighestDimensionUnlessAsked) {
  const View view = squareView(4, true);
  const Vec3 onEdge{0.3, 0, 0};
  EXPECT_NEAR(*ViewProbe(view).scalar(onEdge), linearField(onEdge), 1e-12);
  EXPECT_NEAR(*ViewProbe(view, 0, 1).scalar(onEdge), linearField(onEdge) + 100, 1e-12);
  EXPECT_FALSE(ViewProbe(view, 0, 1).scalar({0.3, 0.3, 0}));
  EXPECT_FALSE(ViewProbe(view, 0, 3).scalar({0.3, 0.3, 0}));
}

TEST(ViewProbe, ReadsTheRequestedStep) {
  View view;
  ElementList& l = view.list(ElementShape::Line, FieldKind::Scalar);
  l.steps = 2;
  l.coordinates = {0, 0, 0, 1, 0, 0};
  l.values = {0, 1, 10, 30};  // step 0: 0, 1; step 1: 10, 30
  EXPECT_NEAR(*ViewProbe(view, 0).scalar({0.5, 0, 0}), 0.5, 1e-12);
  EXPECT_NEAR(*ViewProbe(view, 1).scalar({0.5, 0, 0}), 20, 1e-12);
  EXPECT_FALSE(ViewProbe(view, 2).scalar({0.5, 0, 0}));
}

TEST(ViewProbe, NearestScalarIsTheValueAtTheClosestNode) {
  const View view = squareView(10, false);
  const ViewProbe probe(view);
  EXPECT_FALSE(probe.scalar({3, 0.42, 0}));
  // The nearest node of (3, 0.42) is (1, 0.4); of (-2, -5), the origin.
  EXPECT_NEAR(*probe.nearestScalar({3, 0.42, 0}), linearField({1, 0.4, 0}), 1e-12);
  EXPECT_NEAR(*probe.nearestScalar({-2, -5, 0}), linearField({0, 0, 0}), 1e-12);
  EXPECT_NEAR(*probe.nearestScalar({0.52, 0.29, 0.3}), linearField({0.5, 0.3, 0}), 1e-12);
  EXPECT_FALSE(ViewProbe(View{}).nearestScalar({0, 0, 0}));
  EXPECT_FALSE(ViewProbe(View{}).scalar({0, 0, 0}));
}

TEST(ViewProbe, NearestComponentsOfVectorViews) {
  View view;
  ElementList& l = view.list(ElementShape::Line, FieldKind::Vector);
  l.coordinates = {0, 0, 0, 1, 0, 0};
  l.values = {1, 2, 3, 4, 5, 6};
  int count = 0;
  const auto v = ViewProbe(view).nearestComponents({1.5, 0.3, 0}, &count);
  ASSERT_TRUE(v);
  EXPECT_EQ(count, 3);
  EXPECT_EQ((*v)[0], 4);
  EXPECT_EQ((*v)[2], 6);
  EXPECT_NEAR(*ViewProbe(view).nearestScalar({-1, 0, 0}), std::sqrt(14.0), 1e-12);
}

TEST(ViewProbe, AnswersFromSeveralThreads) {
  const View view = squareView(30, false);
  const ViewProbe probe(view);
  std::vector<int> failures(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int k = 0; k < 2000; ++k) {
        const Vec3 p{std::fmod((k + t) * 0.381966, 1.0), std::fmod(k * 0.5698403, 1.0), 0};
        const auto v = probe.scalar(p);
        if (!v || std::abs(*v - linearField(p)) > 1e-12) ++failures[std::size_t(t)];
      }
    });
  for (std::thread& t : threads) t.join();
  for (int f : failures) EXPECT_EQ(f, 0);
}

}  // namespace
}  // namespace geomesh::post
