// Sizes from views: PostView fields, Background Mesh View, metrics, and the Adapt field.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "mesh/sizes/adapt_size.h"
#include "mesh/sizes/metric_tensor.h"
#include "mesh/sizes/size_field.h"
#include "mesh/views/view.h"
#include "mesh_test_models.h"
#include "size_field_fixtures.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;
using testing::RecordingSink;

constexpr double kUnbounded = 1e22;
const EntityId kSurface{2, 1};

Model square(double lc = 0.5) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, lc)});
  return std::move(b.model);
}

SizeFieldDefinition field(std::string type, std::map<std::string, std::vector<double>> numbers,
                          std::map<std::string, std::string> strings = {}) {
  return {std::move(type), std::move(numbers), std::move(strings)};
}

// The unit square as two triangles, nodal values v(x, y) (9 components for tensors).
void addSquare(post::View& view, post::FieldKind kind,
               const std::function<std::vector<double>(Vec3)>& v) {
  post::ElementList& l = view.list(post::ElementShape::Triangle, kind);
  const Vec3 corners[2][3] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  for (const auto& t : corners)
    for (Vec3 x : t) {
      l.coordinates.insert(l.coordinates.end(), {x.x, x.y, x.z});
      const std::vector<double> values = v(x);
      l.values.insert(l.values.end(), values.begin(), values.end());
    }
}

// View 0: sizes 0.1 + 0.2 x - 0.05 y; view 1: values -1 + 2 x; view 2: a constant tensor;
// view 3: zeros.
post::ViewStore views() {
  post::ViewStore store;
  addSquare(store.add("sizes"), post::FieldKind::Scalar,
            [](Vec3 x) { return std::vector<double>{0.1 + 0.2 * x.x - 0.05 * x.y}; });
  addSquare(store.add("signed"), post::FieldKind::Scalar,
            [](Vec3 x) { return std::vector<double>{-1 + 2 * x.x}; });
  addSquare(store.add("metric"), post::FieldKind::Tensor,
            [](Vec3) { return std::vector<double>{100, 0, 0, 0, 4, 0, 0, 0, 1}; });
  addSquare(store.add("zero"), post::FieldKind::Scalar,
            [](Vec3) { return std::vector<double>{0}; });
  return store;
}

MeshOptions withViews(const post::ViewStore& store, double anisoMax = 1e33) {
  MeshOptions o;
  o.views = &store;
  o.anisoMax = anisoMax;
  return o;
}

TEST(PostViewField, InterpolatesTheViewAndReadsTheNearestNodeOutside) {
  const post::ViewStore store = views();
  Model model = square();
  auto& c = model.meshConstraints();
  c.sizeFields[1] = field("PostView", {{"ViewIndex", {0}}});
  c.sizeFields[2] = field("PostView", {{"IView", {0}}, {"UseClosest", {0}}});
  c.backgroundField = 1;
  RecordingSink log;
  const SizeFields fields(model, log, withViews(store));
  EXPECT_TRUE(log.warnings.empty());
  EXPECT_NEAR(fields.at({0.5, 0.25, 0}, kSurface), 0.1 + 0.1 - 0.0125, 1e-12);
  EXPECT_NEAR(fields.value(1, {3, 0.1, 0}, kSurface), 0.3, 1e-12);  // the node (1, 0)
  EXPECT_NEAR(fields.value(2, {0.5, 0.25, 0}, kSurface), 0.1875, 1e-12);
  EXPECT_EQ(fields.value(2, {3, 0.1, 0}, kSurface), kUnbounded);
}

TEST(PostViewField, CropsValuesAtOrBelowZero) {
  const post::ViewStore store = views();
  Model model = square();
  auto& c = model.meshConstraints();
  c.sizeFields[1] = field("PostView", {{"ViewTag", {1}}});
  c.sizeFields[2] = field("PostView", {{"ViewTag", {1}}, {"CropNegativeValues", {0}}});
  c.sizeFields[3] = field("PostView", {{"ViewIndex", {3}}});
  c.sizeFields[4] = field("PostView", {{"ViewIndex", {3}}, {"CropNegativeValues", {0}}});
  RecordingSink log;
  const SizeFields fields(model, log, withViews(store));
  EXPECT_EQ(fields.value(1, {0.25, 0.1, 0}, kSurface), kUnbounded);
  EXPECT_NEAR(fields.value(1, {0.75, 0.1, 0}, kSurface), 0.5, 1e-12);
  EXPECT_NEAR(fields.value(2, {0.25, 0.1, 0}, kSurface), -0.5, 1e-12);
  EXPECT_EQ(fields.value(3, {0.25, 0.1, 0}, kSurface), kUnbounded);
  EXPECT_EQ(fields.value(4, {0.25, 0.1, 0}, kSurface), 0);
}

TEST(PostViewField, MissingViewWarnsAndReadsUnbounded) {
  const post::ViewStore store = views();
  Model model = square();
  auto& c = model.meshConstraints();
  c.sizeFields[4] = field("PostView", {{"ViewIndex", {7}}});
  c.sizeFields[5] = field("PostView", {{"ViewTag", {9}}});
  c.backgroundView = 12;
  RecordingSink log;
  const SizeFields fields(model, log, withViews(store));
  ASSERT_EQ(log.warnings.size(), 3u);
  EXPECT_NE(log.warnings[0].find("Field[4]"), std::string::npos);
  EXPECT_NE(log.warnings[0].find("index 7"), std::string::npos);
  EXPECT_NE(log.warnings[1].find("Field[5]"), std::string::npos);
  EXPECT_NE(log.warnings[1].find("tag 9"), std::string::npos);
  EXPECT_NE(log.warnings[2].find("Background Mesh View[12]"), std::string::npos);
  EXPECT_EQ(fields.value(4, {0.5, 0.5, 0}, kSurface), kUnbounded);
  EXPECT_FALSE(fields.hasBackground());
  // No store at all: the same, without a crash.
  RecordingSink none;
  const SizeFields without(model, none);
  EXPECT_EQ(without.value(5, {0.5, 0.5, 0}, kSurface), kUnbounded);
  EXPECT_EQ(none.warnings.size(), 3u);
}

TEST(BackgroundMeshView, IsABackgroundAndTheSmallerSizeWins) {
  const post::ViewStore store = views();
  Model model = square();
  auto& c = model.meshConstraints();
  c.backgroundView = 0;
  RecordingSink log;
  {
    const SizeFields fields(model, log, withViews(store));
    EXPECT_TRUE(fields.hasBackground());
    EXPECT_FALSE(fields.hasAnisotropicBackground());
    EXPECT_NEAR(fields.at({0.5, 0.25, 0}, kSurface), 0.1875, 1e-12);
    const auto m = fields.metric({0.5, 0.25, 0}, kSurface);
    ASSERT_TRUE(m);
    const double expected = 1 / (0.1875 * 0.1875);
    EXPECT_NEAR((*m)[0], expected, 1e-9);
    EXPECT_NEAR((*m)[3], expected, 1e-9);
    EXPECT_NEAR((*m)[1], 0, 1e-9);
  }
  c.sizeFields[1] = field("MathEval", {}, {{"F", "0.15"}});
  c.backgroundField = 1;
  const SizeFields fields(model, log, withViews(store));
  EXPECT_NEAR(fields.at({0.5, 0.25, 0}, kSurface), 0.15, 1e-12);
  EXPECT_NEAR(fields.at({0.1, 0.9, 0}, kSurface), 0.1 + 0.02 - 0.045, 1e-12);
  EXPECT_TRUE(log.warnings.empty());
}

TEST(BackgroundMeshView, MeshesAsTheEquivalentField) {
  post::ViewStore store;
  addSquare(store.add("constant"), post::FieldKind::Scalar,
            [](Vec3 x) { return std::vector<double>{0.04 + 0.1 * x.x}; });
  Model byView = square();
  byView.meshConstraints().backgroundView = 0;
  Model byField = square();
  byField.meshConstraints().sizeFields[3] = field("MathEval", {}, {{"F", "0.04 + 0.1 * x"}});
  byField.meshConstraints().backgroundField = 3;
  const std::size_t viewNodes = testing::nodeCount(std::move(byView), withViews(store));
  const std::size_t fieldNodes = testing::nodeCount(std::move(byField), withViews(store));
  EXPECT_EQ(viewNodes, fieldNodes);
  EXPECT_GT(viewNodes, 150u);  // the lc 0.5 corners alone would give a handful
}

TEST(ViewMetric, TensorBackgroundViewGivesItsMetricBounded) {
  const post::ViewStore store = views();
  Model model = square();
  model.meshConstraints().backgroundView = 2;
  RecordingSink log;
  const SizeFields fields(model, log, withViews(store));
  EXPECT_TRUE(fields.hasAnisotropicBackground());
  EXPECT_NEAR(fields.at({0.3, 0.3, 0}, kSurface), 0.1, 1e-12);
  const auto m = fields.metric({0.3, 0.3, 0}, kSurface);
  ASSERT_TRUE(m);
  const double expected[6] = {100, 0, 0, 4, 0, 1};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR((*m)[k], expected[k], 1e-9) << k;
  // Mesh.AnisoMax = 4: eigenvalues at least 100 / 16.
  const SizeFields bounded(model, log, withViews(store, 4));
  const auto b = bounded.metric({0.3, 0.3, 0}, kSurface);
  const double clamped[6] = {100, 0, 0, 6.25, 0, 6.25};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR((*b)[k], clamped[k], 1e-9) << k;
}

TEST(ViewMetric, IntersectsTheFieldAndTheView) {
  const post::ViewStore store = views();
  Model model = square();
  auto& c = model.meshConstraints();
  c.backgroundView = 2;
  c.sizeFields[1] = field("MathEval", {}, {{"F", "0.25"}});  // metric 16 I
  c.backgroundField = 1;
  RecordingSink log;
  const SizeFields fields(model, log, withViews(store));
  const auto m = fields.metric({0.3, 0.3, 0}, kSurface);
  ASSERT_TRUE(m);
  const double expected[6] = {100, 0, 0, 16, 0, 16};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR((*m)[k], expected[k], 1e-9) << k;
}

TEST(ViewMetric, PostViewOfATensorViewAndMathEvalAniso) {
  const post::ViewStore store = views();
  Model model = square();
  auto& c = model.meshConstraints();
  c.sizeFields[1] = field("PostView", {{"ViewIndex", {2}}});
  c.sizeFields[2] = field(
      "MathEvalAniso", {},
      {{"M11", "50"}, {"M22", "20"}, {"M33", "1"}, {"M12", "10"}, {"M13", "0"}, {"M23", "0"}});
  c.backgroundField = 1;
  RecordingSink log;
  {
    const SizeFields fields(model, log, withViews(store));
    EXPECT_TRUE(fields.hasAnisotropicBackground());
    EXPECT_NEAR((*fields.metric({0.5, 0.5, 0}, kSurface))[3], 4, 1e-9);
  }
  c.backgroundField = 2;
  const SizeFields fields(model, log, withViews(store));
  EXPECT_TRUE(fields.hasAnisotropicBackground());
  const auto m = fields.metric({0.5, 0.5, 0}, kSurface);
  const double expected[6] = {50, 10, 0, 20, 0, 1};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR((*m)[k], expected[k], 1e-9) << k;
  // Isotropic fields: I / h^2.
  c.backgroundField = 0;
  c.backgroundView = 0;
  EXPECT_FALSE(SizeFields(model, log, withViews(store)).hasAnisotropicBackground());
}

TEST(MetricTensor, IntersectionIsTheSmallerSizeInEveryDirection) {
  const SymmetricTensor a{10, 3, 0, 2, 0, 1},
      b = tensorFromEigen({1, 30, 5}, {Vec3{0.6, 0.8, 0}, Vec3{-0.8, 0.6, 0}, Vec3{0, 0, 1}});
  const SymmetricTensor m = intersectMetrics(a, b);
  auto length2 = [](const SymmetricTensor& t, Vec3 e) {
    return t[0] * e.x * e.x + t[3] * e.y * e.y + t[5] * e.z * e.z +
           2 * (t[1] * e.x * e.y + t[2] * e.x * e.z + t[4] * e.y * e.z);
  };
  for (int k = 0; k < 100; ++k) {
    const double t = k * 0.0628318, s = k * 0.0371;
    const Vec3 e{std::cos(t) * std::cos(s), std::sin(t) * std::cos(s), std::sin(s)};
    EXPECT_GE(length2(m, e), std::max(length2(a, e), length2(b, e)) * (1 - 1e-9));
  }
  const SymmetricTensor same = intersectMetrics(a, isotropicTensor(1e3));
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(same[k], a[k], 1e-9);
}

// A unit square in n x n cells of two triangles each, the error of element i
// e_i = C(centroid) h_i^p with C(x, y) = 1 + 10 x^2 + y (k = 2, d = 2: p = 3).
post::View errorView(int n) {
  post::View view;
  post::ElementList& l = view.list(post::ElementShape::Triangle, post::FieldKind::Scalar);
  const double h = 1.0 / n;
  const double size = std::sqrt(h * h / 2 / (std::sqrt(3.0) / 4));
  auto add = [&](Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 g = (a + b + c) / 3;
    const double error = (1 + 10 * g.x * g.x + g.y) * std::pow(size, 3);
    for (Vec3 x : {a, b, c}) {
      l.coordinates.insert(l.coordinates.end(), {x.x, x.y, x.z});
      l.values.push_back(error);
    }
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 a{i * h, j * h, 0}, b{(i + 1) * h, j * h, 0}, c{(i + 1) * h, (j + 1) * h, 0},
          d{i * h, (j + 1) * h, 0};
      add(a, b, c);
      add(a, c, d);
    }
  return view;
}

TEST(AdaptField, TargetCountIsMetAndErrorsEquidistributed) {
  const post::View view = errorView(12);
  AdaptOptions o;
  o.targetElements = 5000;
  std::string why;
  const auto r = adaptSizes(view, o, why);
  ASSERT_TRUE(r) << why;
  EXPECT_EQ(r->dimension, 2);
  ASSERT_EQ(r->newSizes.size(), 288u);
  double count = 0, first = -1;
  for (std::size_t i = 0; i < r->newSizes.size(); ++i) {
    const double c = r->errors[i] / std::pow(r->sizes[i], 3);
    const double newError = c * std::pow(r->newSizes[i], 3);
    if (first < 0) first = newError;
    EXPECT_NEAR(newError / first, 1, 1e-12);
    count += r->measures[i] / (std::sqrt(3.0) / 4 * r->newSizes[i] * r->newSizes[i]);
  }
  EXPECT_NEAR(count, 5000, 1e-9);
  EXPECT_NEAR(r->predictedElements, 5000, 1e-9);
  // Where C is larger the sizes are smaller, as C^(-1/3).
  EXPECT_LT(r->newSizes.back(), r->newSizes.front());
}

TEST(AdaptField, TargetErrorIsMet) {
  const post::View view = errorView(8);
  AdaptOptions o;
  o.targetError = 1e-3;
  std::string why;
  const auto r = adaptSizes(view, o, why);
  ASSERT_TRUE(r) << why;
  double error2 = 0;
  for (std::size_t i = 0; i < r->newSizes.size(); ++i) {
    const double c = r->errors[i] / std::pow(r->sizes[i], 3);
    const double n = r->measures[i] / (std::sqrt(3.0) / 4 * r->newSizes[i] * r->newSizes[i]);
    error2 += n * std::pow(c * std::pow(r->newSizes[i], 3), 2);
  }
  EXPECT_NEAR(std::sqrt(error2), 1e-3, 1e-12);
  EXPECT_NEAR(r->predictedError, 1e-3, 1e-12);
  // Halving the target error with k = 2 multiplies the element count by 2^(d/k) = 2.
  o.targetError = 5e-4;
  EXPECT_NEAR(adaptSizes(view, o, why)->predictedElements / r->predictedElements, 2, 1e-9);
}

TEST(AdaptField, FieldInterpolatesNodalMeansAndClamps) {
  post::ViewStore store;
  store.add("error") = errorView(4);
  Model model = square();
  auto& c = model.meshConstraints();
  c.sizeFields[1] = field("Adapt", {{"View", {0}}, {"TargetElements", {100}}});
  c.sizeFields[2] = field("Adapt", {{"View", {0}}, {"TargetElements", {100}}, {"SizeMax", {0.05}}});
  c.sizeFields[3] = field("Adapt", {{"View", {0}}, {"TargetElements", {10}}, {"TargetError", {1}}});
  c.sizeFields[4] = field("Adapt", {{"TargetElements", {10}}});
  RecordingSink log;
  const SizeFields fields(model, log, withViews(store));
  ASSERT_EQ(log.warnings.size(), 2u);
  EXPECT_NE(log.warnings[0].find("Field[3]"), std::string::npos);
  EXPECT_NE(log.warnings[1].find("Field[4]"), std::string::npos);
  EXPECT_EQ(fields.value(3, {0.5, 0.5, 0}, kSurface), kUnbounded);
  EXPECT_EQ(fields.value(4, {0.5, 0.5, 0}, kSurface), kUnbounded);
  // The corners (0, 0) and (1, 1) belong to the two triangles of the first and last cells:
  // the geometric mean of their sizes; beyond the view, the nearest node's size.
  AdaptOptions o;
  o.targetElements = 100;
  std::string why;
  const auto r = adaptSizes(store.at(0), o, why);
  const std::size_t last = r->newSizes.size() - 1;
  EXPECT_NEAR(fields.value(1, {1, 1, 0}, kSurface),
              std::sqrt(r->newSizes[last] * r->newSizes[last - 1]), 1e-12);
  EXPECT_NEAR(fields.value(1, {0, 0, 0}, kSurface), std::sqrt(r->newSizes[0] * r->newSizes[1]),
              1e-12);
  EXPECT_NEAR(fields.value(1, {1.5, 1.5, 0}, kSurface), fields.value(1, {1, 1, 0}, kSurface),
              1e-15);
  EXPECT_EQ(fields.value(2, {0.5, 0.5, 0}, kSurface), 0.05);
}

// The mesh an Adapt field makes has about the number of triangles it targets (the boundary
// and the nodal smoothing of the sizes account for the difference).
TEST(AdaptField, MeshHasAboutTheTargetCount) {
  post::ViewStore store;
  store.add("error") = errorView(8);
  Model model = square(1);
  model.meshConstraints().sizeFields[1] =
      field("Adapt", {{"View", {0}}, {"TargetElements", {1000}}});
  model.meshConstraints().backgroundField = 1;
  MeshOptions options = withViews(store);
  options.sizeFromPoints = false;
  options.sizeExtendFromBoundary = false;
  Mesh mesh;
  RecordingSink log;
  generateMesh(model, options, 2, mesh, log);
  EXPECT_GT(mesh.elementCount(2), 850u);
  EXPECT_LT(mesh.elementCount(2), 1200u);
}

}  // namespace
}  // namespace geomesh
