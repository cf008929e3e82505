// Reading BREP, STEP and IGES files into the OpenCASCADE factory, and the seams and poles of the
// imported faces as the model sees them.
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "tests/occ_fixtures.h"

namespace geomesh {
namespace {

using namespace occ_fixtures;

struct Counts {
  std::size_t points, curves, surfaces, volumes;
};

Counts countsOf(const Model& model) {
  return {model.points().size(), model.curves().size(), model.surfaces().size(),
          model.volumes().size()};
}

Counts importAndCount(const std::string& path, std::vector<EntityId>* top = nullptr) {
  OccFactory occ;
  const std::vector<EntityId> shapes = occ.importShapes(path);
  if (top) *top = shapes;
  Model model;
  occ.synchronize(model);
  return countsOf(model);
}

TEST(OccImport, BrepCylinderHasASeam) {
  std::vector<EntityId> top;
  const Counts c = importAndCount(writeBrep(cylinder()), &top);
  EXPECT_EQ(top, (std::vector<EntityId>{{3, 1}}));
  EXPECT_EQ(c.volumes, 1u);
  EXPECT_EQ(c.surfaces, 3u);
  EXPECT_EQ(c.curves, 3u);  // two circles and the seam
  EXPECT_EQ(c.points, 2u);
}

TEST(OccImport, StepPartsKeepTheirTopology) {
  const Counts sphere_ = importAndCount(writeStep(sphere()));
  EXPECT_EQ(sphere_.volumes, 1u);
  EXPECT_EQ(sphere_.surfaces, 1u);
  EXPECT_EQ(sphere_.curves, 3u);  // the seam and two poles
  const Counts box = importAndCount(writeStep(boxWithHole()));
  EXPECT_EQ(box.volumes, 1u);
  EXPECT_EQ(box.surfaces, 7u);
}

TEST(OccImport, IgesFacesComeInWithoutSolid) {
  const std::string path = scratch::path("box.igs").string();
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 1);  // BRep mode: faces share their edges
  writer.AddShape(BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape());
  writer.ComputeModel();
  ASSERT_TRUE(writer.Write(path.c_str()));
  std::vector<EntityId> top;
  ::testing::internal::CaptureStdout();  // the reader's progress stays off standard output
  const Counts c = importAndCount(path, &top);
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(c.surfaces, 6u);
  EXPECT_EQ(c.points, 8u);
  ASSERT_FALSE(top.empty());
}

TEST(OccImport, MissingOrUnreadableFileNamesThePath) {
  OccFactory occ;
  const std::string missing = scratch::path("missing.step").string();
  try {
    occ.importShapes(missing);
    FAIL() << "no error";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  const std::string garbage = scratch::path("garbage.brep").string();
  { std::ofstream(garbage) << "not a shape\n"; }
  EXPECT_THROW(occ.importShapes(garbage), GeometryError);
  EXPECT_EQ(occ.maxTag(3), 0);
}

TEST(OccImport, ImportedTagsFollowExistingOnes) {
  OccFactory occ;
  occ.addBox(1, {5, 0, 0}, {1, 1, 1});
  const std::vector<EntityId> top = occ.importShapes(writeBrep(cylinder()));
  EXPECT_EQ(top, (std::vector<EntityId>{{3, 2}}));
  EXPECT_EQ(occ.maxTag(2), 9);
}

// The seam's two occurrences lie on the two sides of the parameter box; a pole's curve runs
// along a side at the pole's latitude.
TEST(OccImport, SeamAndPoleParametersOnTheFace) {
  OccFactory occ;
  occ.importShapes(writeBrep(sphere()));
  Model model;
  occ.synchronize(model);
  const ModelSurface& s = model.surfaces().begin()->second;
  ASSERT_EQ(s.loops.size(), 1u);
  ASSERT_EQ(s.loops[0].size(), 4u);
  int seams = 0, poles = 0;
  const double pi = std::numbers::pi;
  for (int c : s.loops[0]) {
    const ModelCurve& curve = *model.curve(std::abs(c));
    const Interval r = curve.geometry->range();
    const auto a = s.geometry->curveParameters(c, r.min);
    const auto b = s.geometry->curveParameters(c, r.max);
    ASSERT_TRUE(a && b);
    if (curve.geometry->isDegenerate()) {
      ++poles;
      EXPECT_NEAR(std::abs(a->v), pi / 2, 1e-9);
      EXPECT_NEAR(std::abs(a->u - b->u), 2 * pi, 1e-9);
    } else {
      ++seams;
      EXPECT_NEAR(std::abs(b->v - a->v), pi, 1e-9);
    }
  }
  EXPECT_EQ(poles, 2);
  EXPECT_EQ(seams, 2);
  // The seam, used in both directions, lies at u = 0 one way and u = 2 pi the other.
  int seam = 0;
  for (int c : s.loops[0])
    if (!model.curve(std::abs(c))->geometry->isDegenerate()) seam = std::abs(c);
  const double t = model.curve(seam)->geometry->range().min;
  const auto forward = s.geometry->curveParameters(seam, t);
  const auto backward = s.geometry->curveParameters(-seam, t);
  ASSERT_TRUE(forward && backward);
  EXPECT_NEAR(std::abs(forward->u - backward->u), 2 * pi, 1e-9);
}

}  // namespace
}  // namespace geomesh
