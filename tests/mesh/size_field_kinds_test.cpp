// Tests of the derived, anisotropic, boundary and automatic size fields: values at points
// computed by hand from their definitions, and meshes against the reference's node counts.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mesh/checks/mesh_check.h"
#include "mesh/pipeline/generate.h"
#include "mesh/sizes/automatic_size.h"
#include "mesh/sizes/finite_differences.h"
#include "mesh/sizes/size_field.h"
#include "mesh_test_models.h"
#include "size_field_fixtures.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;

constexpr double kUnbounded = 1e22;
constexpr EntityId kSurface{2, 1};

using testing::nodeCount;
using testing::RecordingSink;

SizeFieldDefinition field(std::string type, std::map<std::string, std::vector<double>> numbers,
                          std::map<std::string, std::string> strings = {}) {
  return {std::move(type), std::move(numbers), std::move(strings)};
}

// The unit square with lc 0.1 and a free point 5 at its centre (as in size_field_test.cpp).
Model square() {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  b.point(0.5, 0.5, 0.1);
  return std::move(b.model);
}

// ---- values at points, from the definitions ----

TEST(SizeFieldKinds, FrustumInterpolatesOverItsShellOnly) {
  Model model = square();
  model.meshConstraints().sizeFields[1] = field("Frustum", {{"X1", {0}},
                                                            {"Y1", {0.5}},
                                                            {"Z1", {0}},
                                                            {"X2", {1}},
                                                            {"Y2", {0.5}},
                                                            {"Z2", {0}},
                                                            {"InnerR1", {0.1}},
                                                            {"OuterR1", {0.3}},
                                                            {"R2_inner", {0.05}},
                                                            {"OuterR2", {0.45}},
                                                            {"InnerV1", {0.02}},
                                                            {"OuterV1", {0.1}},
                                                            {"InnerV2", {0.04}},
                                                            {"OuterV2", {0.2}}});
  RecordingSink log;
  const SizeFields f(model, log);
  EXPECT_TRUE(log.warnings.empty());
  // u = 0.5, r = 0.25: radii 0.075 and 0.375, v = 0.175 / 0.3; sizes 0.03 inside, 0.15 outside.
  const double v = 0.175 / 0.3;
  EXPECT_NEAR(f.value(1, {0.5, 0.75, 0}, kSurface), (1 - v) * 0.03 + v * 0.15, 1e-12);
  EXPECT_NEAR(f.value(1, {0, 0.75, 0}, kSurface), 0.08, 1e-12);  // u = 0, v = 0.75
  EXPECT_GT(f.value(1, {0.5, 0.5, 0}, kSurface), 1e21);          // inside the inner radius
  EXPECT_GT(f.value(1, {0.5, 0.95, 0}, kSurface), 1e21);         // beyond the outer radius
  EXPECT_GT(f.value(1, {-0.1, 0.75, 0}, kSurface), 1e21);        // before the first end
}

TEST(SizeFieldKinds, ParamEvaluatesItsFieldAtMappedPoints) {
  Model model = square();
  auto& c = model.meshConstraints();
  c.sizeFields[1] = field("MathEval", {}, {{"F", "0.02 + 0.1*x + 0.01*y"}});
  c.sizeFields[2] = field("Param", {{"InField", {1}}}, {{"FX", "1 - y"}, {"FY", "x"}});
  RecordingSink log;
  const SizeFields f(model, log);
  EXPECT_TRUE(log.warnings.empty());
  EXPECT_NEAR(f.value(2, {0.3, 0.2, 0}, kSurface), 0.02 + 0.08 + 0.003, 1e-12);
  c.sizeFields[2].strings.clear();  // empty formulas stand for the coordinates themselves
  EXPECT_NEAR(SizeFields(model, log).value(2, {0.3, 0.2, 0}, kSurface), 0.052, 1e-12);
}

TEST(SizeFieldKinds, GradientComponentsAndNorm) {
  Model model = square();
  auto& c = model.meshConstraints();
  c.sizeFields[1] = field("MathEval", {}, {{"F", "x^2 + 3*y"}});
  for (int kind = 0; kind <= 4; ++kind)
    c.sizeFields[10 + kind] =
        field("Gradient", {{"InField", {1}}, {"Kind", {double(kind)}}, {"Delta", {0.01}}});
  c.sizeFields[20] = field("Gradient", {{"IField", {1}}});  // Kind 3 and Delta 1e-4 by default
  RecordingSink log;
  const SizeFields f(model, log);
  ASSERT_EQ(log.warnings.size(), 1u);  // Kind 4
  const Vec3 p{0.5, 0.2, 0};
  EXPECT_NEAR(f.value(10, p, kSurface), 1, 1e-9);  // central differences are exact here
  EXPECT_NEAR(f.value(11, p, kSurface), 3, 1e-9);
  EXPECT_NEAR(f.value(12, p, kSurface), 0, 1e-9);
  EXPECT_NEAR(f.value(13, p, kSurface), std::sqrt(10.0), 1e-9);
  EXPECT_GT(f.value(14, p, kSurface), 1e21);
  EXPECT_NEAR(f.value(20, p, kSurface), std::sqrt(10.0), 1e-6);
}

TEST(SizeFieldKinds, CurvatureLaplacianHessianMean) {
  Model model = square();
  const int centre = 5;  // the free point at (0.5, 0.5)
  auto& c = model.meshConstraints();
  c.sizeFields[1] = field("Distance", {{"PointsList", {double(centre)}}});
  c.sizeFields[2] = field("Curvature", {{"InField", {1}}});
  c.sizeFields[3] = field("MathEval", {}, {{"F", "x^2 + 2*y^2 + 3*z^2"}});
  c.sizeFields[4] = field("Laplacian", {{"InField", {3}}});
  c.sizeFields[5] = field("MathEval", {}, {{"F", "x^2 + x*y"}});
  c.sizeFields[6] = field("MaxEigenHessian", {{"InField", {5}}, {"Delta", {0.01}}});
  c.sizeFields[7] = field("MathEval", {}, {{"F", "x^2"}});
  c.sizeFields[8] = field("Mean", {{"InField", {7}}, {"Delta", {0.1}}});
  c.sizeFields[9] = field("Octree", {{"InField", {7}}});
  RecordingSink log;
  const SizeFields f(model, log);
  EXPECT_TRUE(log.warnings.empty());
  // The distance to a point is a cone in 3D: div of its unit gradient is 2 / r.
  EXPECT_NEAR(f.value(2, {2.5, 0.5, 0}, kSurface), 1, 1e-4);
  EXPECT_NEAR(f.value(4, {0.3, 0.7, 0.1}, kSurface), 12, 1e-6);
  // Hessian [[2, 1, 0], [1, 0, 0], [0, 0, 0]]: eigenvalues 1 +- sqrt(2) and 0.
  EXPECT_NEAR(f.value(6, {0.3, 0.7, 0}, kSurface), 1 + std::sqrt(2.0), 1e-8);
  // (7 x^2 + 2 Delta^2) / 7 at x = 1.
  EXPECT_NEAR(f.value(8, {1, 0.4, 0}, kSurface), 1 + 0.02 / 7, 1e-12);
  EXPECT_NEAR(f.value(9, {0.7, 0.4, 0}, kSurface), 0.49, 1e-12);
}

TEST(SizeFieldKinds, LargestEigenvalueOfSymmetricMatrices) {
  EXPECT_NEAR(largestEigenvalue({3, 1, 2, 0, 0, 0}), 3, 1e-12);
  EXPECT_NEAR(largestEigenvalue({-1, -2, -3, 0, 0, 0}), -1, 1e-12);
  // [[2, 1, 1], [1, 2, 1], [1, 1, 2]]: eigenvalues 4, 1, 1.
  EXPECT_NEAR(largestEigenvalue({2, 2, 2, 1, 1, 1}), 4, 1e-12);
}

TEST(SizeFieldKinds, AnisotropicFieldsReadTheirSmallestSize) {
  Model model = square();
  auto& c = model.meshConstraints();
  c.sizeFields[1] = field(
      "MathEvalAniso", {},
      {{"M11", "100"}, {"M22", "100"}, {"M33", "0"}, {"M12", "50"}, {"M13", "0"}, {"M23", "0"}});
  c.sizeFields[2] =
      field("MathEvalAniso", {},
            {{"M11", "-1"}, {"M22", "0"}, {"M33", "0"}, {"M12", "0"}, {"M13", "0"}, {"M23", "0"}});
  c.sizeFields[3] = field("AttractorAnisoCurve", {{"CurvesList", {1}},
                                                  {"Sampling", {101}},
                                                  {"DistMin", {0.1}},
                                                  {"DistMax", {0.5}},
                                                  {"lMinTangent", {0.2}},
                                                  {"SizeMaxTangent", {0.3}},
                                                  {"SizeMinNormal", {0.03}},
                                                  {"SizeMaxNormal", {0.5}}});
  RecordingSink log;
  const SizeFields f(model, log);
  EXPECT_TRUE(log.warnings.empty());
  EXPECT_NEAR(f.value(1, {0.2, 0.3, 0}, kSurface), 1 / std::sqrt(150.0), 1e-12);
  EXPECT_GT(f.value(2, {0.2, 0.3, 0}, kSurface), 1e21);
  // Curve 1 is y = 0, sampled every 0.01: the distance from (0.5, y) is y.
  EXPECT_NEAR(f.value(3, {0.5, 0.05, 0}, kSurface), 0.03, 1e-12);  // normal, at DistMin
  EXPECT_NEAR(f.value(3, {0.5, 0.3, 0}, kSurface), 0.25, 1e-12);   // tangent 0.25, normal 0.265
  EXPECT_NEAR(f.value(3, {0.5, 0.6, 0}, kSurface), 0.3, 1e-12);    // beyond DistMax
}

// The unit square with size 0.02 at its first corner and 0.1 at the others.
Model squareWithAFineCorner() {
  PolygonModelBuilder b;
  std::vector<int> loop;
  const int p1 = b.point(0, 0, 0.02), p2 = b.point(1, 0, 0.1), p3 = b.point(1, 1, 0.1),
            p4 = b.point(0, 1, 0.1);
  b.surface({{b.line(p1, p2), b.line(p2, p3), b.line(p3, p4), b.line(p4, p1)}});
  return std::move(b.model);
}

TEST(SizeFieldKinds, ExtendCarriesBoundaryEdgeLengthsInwards) {
  Model model = squareWithAFineCorner();
  model.meshConstraints().sizeFields[1] =
      field("Extend", {{"CurvesList", {1, 2, 3, 4}}, {"DistMax", {0.3}}, {"SizeMax", {0.2}}});
  RecordingSink log;
  const SizeFields f(model, log);
  EXPECT_TRUE(log.warnings.empty());
  // Curve 2 (x = 1) gets 10 edges of 0.1: the one nearest (0.9, 0.55) has its midpoint at
  // (1, 0.55), d = 0.1, f = 2/3.
  EXPECT_NEAR(f.value(1, {0.9, 0.55, 0}, kSurface), 2.0 / 3 * 0.1 + 1.0 / 3 * 0.2, 1e-9);
  EXPECT_NEAR(f.value(1, {0.5, 0.5, 0}, kSurface), 0.2, 1e-12);  // beyond DistMax
  EXPECT_GT(f.value(1, {0.9, 0.55, 0}, {1, 2}), 1e21);           // not on curves
  model.meshConstraints().sizeFields[1].numbers["Power"] = {2};
  EXPECT_NEAR(SizeFields(model, log).value(1, {0.9, 0.55, 0}, kSurface),
              4.0 / 9 * 0.1 + 5.0 / 9 * 0.2, 1e-9);
}

// A disk of radius 0.5 and a strip 1 x 0.05, as 2D models.
Model disk() {
  PolygonModelBuilder b;
  b.surface({b.circle({0, 0}, 0.5, 1)});
  return std::move(b.model);
}
Model strip() {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 0.05}, {0, 0.05}}, 1)});
  return std::move(b.model);
}

TEST(SizeFieldKinds, AutomaticSizeFollowsCurvatureWithGradation) {
  Model model = disk();
  model.meshConstraints().sizeFields[1] =
      field("AutomaticMeshSizeField", {{"hBulk", {0.2}}, {"nPointsPerCircle", {40}}});
  RecordingSink log;
  const SizeFields f(model, log);
  EXPECT_TRUE(log.warnings.empty());
  const double onCircle = 2 * 3.14159265358979323846 / (40 * 2);  // curvature 2
  EXPECT_NEAR(f.value(1, {0.5, 0, 0}, kSurface), onCircle, 1e-6);
  EXPECT_NEAR(f.value(1, {0, 0, 0}, kSurface), onCircle + 0.1 * 0.5, 1e-6);
  model.meshConstraints().sizeFields[1].numbers["gradation"] = {1.3};
  model.meshConstraints().sizeFields[1].numbers["hMin"] = {0.1};
  EXPECT_NEAR(SizeFields(model, log).value(1, {0.5, 0, 0}, kSurface), 0.1, 1e-12);
  EXPECT_NEAR(SizeFields(model, log).value(1, {0, 0, 0}, kSurface), 0.2, 1e-12);
}

TEST(SizeFieldKinds, AutomaticSizeResolvesThinGaps) {
  Model model = strip();
  AutomaticSize::Options o;
  o.hBulk = 0.1;
  const AutomaticSize size(model, o);
  // Two layers across the gap of 0.05: 0.025 on both long sides, 0.0275 halfway.
  EXPECT_NEAR(size.at({0.5, 0, 0}), 0.025, 1e-9);
  EXPECT_NEAR(size.at({0.5, 0.025, 0}), 0.0275, 1e-9);
  o.features = false;
  EXPECT_NEAR(AutomaticSize(model, o).at({0.5, 0.025, 0}), 0.1, 1e-12);
  o.features = true;
  o.hMax = 0.02;
  EXPECT_NEAR(AutomaticSize(model, o).at({0.5, 0.025, 0}), 0.02, 1e-12);
}

TEST(SizeFieldKinds, AutomaticSizeWarnsForWhatItDoesNotFollow) {
  Model model = disk();
  model.meshConstraints().sizeFields[1] =
      field("AutomaticMeshSizeField", {{"smoothing", {0}}}, {{"p4estFileToLoad", "sizes.p4est"}});
  RecordingSink log;
  const SizeFields f(model, log);
  ASSERT_EQ(log.warnings.size(), 2u);
  EXPECT_NE(log.warnings[0].find("p4estFileToLoad is not followed"), std::string::npos);
  EXPECT_NE(log.warnings[1].find("smoothing = 0 is not followed"), std::string::npos);
  // hBulk unset: the model's default size, a tenth of its box's diagonal.
  EXPECT_NEAR(f.value(1, {0, 0, 0}, kSurface), 0.1 * std::sqrt(2.0), 1e-9);
}

TEST(SizeFieldKinds, ExternalProcessIsRefusedAndReadsUnbounded) {
  Model model = square();
  auto& c = model.meshConstraints();
  c.sizeFields[1] = field("ExternalProcess", {}, {{"CommandLine", "python3 size.py"}});
  c.sizeFields[2] = field("Min", {{"FieldsList", {1}}});
  c.backgroundField = 1;
  RecordingSink log;
  const SizeFields f(model, log);
  ASSERT_EQ(log.warnings.size(), 1u);
  EXPECT_NE(log.warnings[0].find("geomesh does not run external programs"), std::string::npos);
  EXPECT_NE(log.warnings[0].find("python3 size.py"), std::string::npos);
  EXPECT_TRUE(f.hasBackground());
  EXPECT_EQ(f.at({0.5, 0.5, 0}, kSurface), kUnbounded);
  EXPECT_EQ(f.value(2, {0.5, 0.5, 0}, kSurface), kUnbounded);
}

TEST(SizeFieldKinds, DerivedFieldsReadingThemselvesAreCycles) {
  Model model = square();
  model.meshConstraints().sizeFields[1] = field("Laplacian", {});  // InField 1 by default
  model.meshConstraints().sizeFields[2] = field("Param", {{"InField", {3}}}, {{"FX", "F2"}});
  model.meshConstraints().sizeFields[3] = field("MathEval", {}, {{"F", "1"}});
  RecordingSink log;
  const SizeFields f(model, log);
  EXPECT_EQ(log.warnings.size(), 2u);
  EXPECT_GT(f.value(1, {0, 0, 0}, kSurface), 1e21);
  EXPECT_GT(f.value(2, {0, 0, 0}, kSurface), 1e21);
}

// ---- meshes against the reference ----


// Within `tolerance` (a fraction) of the reference's node count for the same definitions.
void expectNodesNear(std::size_t actual, double reference, double tolerance = 0.12) {
  EXPECT_GT(static_cast<double>(actual), (1 - tolerance) * reference);
  EXPECT_LT(static_cast<double>(actual), (1 + tolerance) * reference);
}

// The unit square (with its free centre point) meshed with background field `background`.
std::size_t squareNodes(std::map<int, SizeFieldDefinition> fields, int background,
                        std::vector<Vec3> freePoints = {}) {
  Model model = square();
  for (Vec3 p : freePoints) model.addPoint({6, p, 0});
  model.meshConstraints().sizeFields = std::move(fields);
  model.meshConstraints().backgroundField = background;
  return nodeCount(std::move(model));
}

// Reference Gmsh 4.15.2: 412 nodes.
TEST(SizeFieldKinds, FrustumMatchesTheReference) {
  expectNodesNear(squareNodes({{1, field("Frustum", {{"X1", {0}},
                                                     {"Y1", {0.5}},
                                                     {"Z1", {0}},
                                                     {"X2", {1}},
                                                     {"Y2", {0.5}},
                                                     {"Z2", {0}},
                                                     {"InnerR1", {0}},
                                                     {"OuterR1", {0.3}},
                                                     {"InnerR2", {0}},
                                                     {"OuterR2", {0.5}},
                                                     {"InnerV1", {0.02}},
                                                     {"OuterV1", {0.1}},
                                                     {"InnerV2", {0.04}},
                                                     {"OuterV2", {0.1}}})}},
                              1),
                  412);
}

// Reference: 638 nodes.
TEST(SizeFieldKinds, ParamMatchesTheReference) {
  expectNodesNear(
      squareNodes(
          {{1, field("MathEval", {}, {{"F", "0.02+0.1*x"}})},
           {2, field("Param", {{"InField", {1}}}, {{"FX", "1-y"}, {"FY", "x"}, {"FZ", "z"}})}},
          2),
      638);
}

// Reference: 447 nodes.
TEST(SizeFieldKinds, GradientMatchesTheReference) {
  expectNodesNear(squareNodes({{1, field("MathEval", {}, {{"F", "0.02*(x+1)^2+0.01*y"}})},
                               {2, field("Gradient", {{"InField", {1}}})}},
                              2),
                  447);
}

// 0.05 / r around (-0.5, -0.5): reference 317 nodes (its free point included, as here).
TEST(SizeFieldKinds, CurvatureMatchesTheReference) {
  expectNodesNear(squareNodes({{1, field("Distance", {{"PointsList", {6}}})},
                               {2, field("Curvature", {{"InField", {1}}, {"Delta", {0.001}}})},
                               {3, field("MathEval", {}, {{"F", "0.05*F2"}})}},
                              3, {{-0.5, -0.5, 0}}),
                  317);
}

// Reference: 467 nodes.
TEST(SizeFieldKinds, LaplacianMatchesTheReference) {
  expectNodesNear(squareNodes({{1, field("MathEval", {}, {{"F", "0.005*x^4+0.02*y^2"}})},
                               {2, field("Laplacian", {{"InField", {1}}, {"Delta", {0.001}}})}},
                              2),
                  467);
}

// 0.03 r around (-0.5, -0.5): reference 823 nodes.
TEST(SizeFieldKinds, MaxEigenHessianMatchesTheReference) {
  expectNodesNear(
      squareNodes({{1, field("Distance", {{"PointsList", {6}}})},
                   {2, field("MaxEigenHessian", {{"InField", {1}}, {"Delta", {0.001}}})},
                   {3, field("MathEval", {}, {{"F", "0.03/F2"}})}},
                  3, {{-0.5, -0.5, 0}}),
      823);
}

// The mean of a box's sizes: reference 193 nodes.
TEST(SizeFieldKinds, MeanMatchesTheReference) {
  expectNodesNear(squareNodes({{1, field("Box", {{"VIn", {0.02}},
                                                 {"VOut", {0.1}},
                                                 {"XMin", {0.3}},
                                                 {"XMax", {0.6}},
                                                 {"YMin", {0.3}},
                                                 {"YMax", {0.6}}})},
                               {2, field("Mean", {{"InField", {1}}, {"Delta", {0.05}}})}},
                              2),
                  193);
}

// Reference: 604 nodes (its octree reads piecewise constant values; geomesh the field: 635).
TEST(SizeFieldKinds, OctreeMatchesTheReference) {
  expectNodesNear(squareNodes({{1, field("MathEval", {}, {{"F", "0.02+0.1*x"}})},
                               {2, field("Octree", {{"InField", {1}}})}},
                              2),
                  604);
}

// Isotropic meshers follow the smaller of the tangent and normal sizes, here the normal one:
// the reference meshes the same sizes given as Threshold of Distance with 765 nodes. (Its own
// isotropic meshers read AttractorAnisoCurve's distance as the size: 230 nodes.)
TEST(SizeFieldKinds, AttractorAnisoCurveMatchesTheReferenceIsotropicEquivalent) {
  expectNodesNear(squareNodes({{1, field("AttractorAnisoCurve", {{"CurvesList", {1}},
                                                                 {"Sampling", {100}},
                                                                 {"DistMin", {0.05}},
                                                                 {"DistMax", {0.4}},
                                                                 {"SizeMinTangent", {0.1}},
                                                                 {"SizeMaxTangent", {0.2}},
                                                                 {"SizeMinNormal", {0.015}},
                                                                 {"SizeMaxNormal", {0.1}}})}},
                              1),
                  765);
}

// The metric's smallest size is (0.03 + 0.05 x) / sqrt(1.5): the reference meshes that
// MathEval with 871 nodes. (Its own isotropic meshers read M11 as the size: 143 nodes.)
TEST(SizeFieldKinds, MathEvalAnisoMatchesTheReferenceIsotropicEquivalent) {
  const std::string a = "1/(0.03+0.05*x)^2";
  expectNodesNear(squareNodes({{1, field("MathEvalAniso", {},
                                         {{"M11", a},
                                          {"M22", a},
                                          {"M33", "1"},
                                          {"M12", "0.5/(0.03+0.05*x)^2"},
                                          {"M13", "0"},
                                          {"M23", "0"}})}},
                              1),
                  871);
}

// Reference: 162 nodes (Mesh.MeshSizeExtendFromBoundary = 0).
TEST(SizeFieldKinds, ExtendMatchesTheReference) {
  Model model = squareWithAFineCorner();
  model.meshConstraints().sizeFields[1] =
      field("Extend", {{"CurvesList", {1, 2, 3, 4}}, {"DistMax", {0.3}}, {"SizeMax", {0.2}}});
  model.meshConstraints().backgroundField = 1;
  MeshOptions options;
  options.sizeExtendFromBoundary = false;
  expectNodesNear(nodeCount(std::move(model), options), 162);
}

MeshOptions fieldAlone() {
  MeshOptions options;
  options.sizeFromPoints = false;
  options.sizeExtendFromBoundary = false;
  return options;
}

// The reference cannot evaluate AutomaticMeshSizeField (its build lacks the octree
// libraries). The sizes it defines here, 2 Pi / (40 * 2) on the circle growing by 0.1 per
// unit of distance up to 0.2, the reference meshes as Threshold of Distance with 140 nodes.
TEST(SizeFieldKinds, AutomaticCurvatureMatchesTheReferenceEquivalent) {
  Model model = disk();
  model.meshConstraints().sizeFields[1] =
      field("AutomaticMeshSizeField", {{"hBulk", {0.2}}, {"nPointsPerCircle", {40}}});
  model.meshConstraints().backgroundField = 1;
  expectNodesNear(nodeCount(std::move(model), fieldAlone()), 140);
}

// Two layers across the strip's width, 0.025 + 0.1 d from its long sides: the reference meshes
// that MathEval with 126 nodes.
TEST(SizeFieldKinds, AutomaticGapMatchesTheReferenceEquivalent) {
  Model model = strip();
  model.meshConstraints().sizeFields[1] =
      field("AutomaticMeshSizeField", {{"hBulk", {0.1}}, {"nPointsPerGap", {2}}});
  model.meshConstraints().backgroundField = 1;
  expectNodesNear(nodeCount(std::move(model), fieldAlone()), 126);
}

}  // namespace
}  // namespace geomesh
