// The OpenCASCADE factory's CAD files: what it writes, it reads back with the same shapes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

OccFactory boxAndBall() {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 2, 3});
  occ.addSphere(2, {5, 0, 0}, 1);
  occ.addRectangle(20, {0, 10, 0}, 1, 1);
  return occ;
}

void expectRoundTrip(const std::string& name) {
  const std::string path = scratch::path(name);
  boxAndBall().exportShapes(path);
  OccFactory read;
  read.addBox(1, {20, 0, 0}, {1, 1, 1});  // read shapes take the next free tags
  const std::vector<EntityId> r = read.importShapes(path);
  EXPECT_EQ(r, (std::vector<EntityId>{{3, 2}, {3, 3}}));
  EXPECT_NEAR(read.volume(2), 6, 1e-6);
  EXPECT_NEAR(read.volume(3), 4 * std::numbers::pi / 3, 1e-6);
  // The highest dimension only, as the reference imports: the rectangle stays behind.
  EXPECT_EQ(read.tags(2).size(), 6u + 6u + 1u);
  std::filesystem::remove(path);
}

TEST(OccImport, BrepRoundTrip) { expectRoundTrip("occ-round-trip.brep"); }
TEST(OccImport, StepRoundTrip) { expectRoundTrip("occ-round-trip.step"); }

TEST(OccImport, BadFilesNameThePath) {
  OccFactory occ;
  try {
    occ.importShapes("/nonexistent/part.step");
    FAIL() << "a missing file was accepted";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/part.step"), std::string::npos);
  }
  const std::string garbage = scratch::path("occ-garbage.step");
  std::ofstream(garbage) << "not a step file\n";
  EXPECT_THROW(occ.importShapes(garbage), GeometryError);
  std::filesystem::remove(garbage);
  EXPECT_THROW(occ.importShapes(scratch::path("occ-part.xyz")), GeometryError);
}

}  // namespace
}  // namespace geomesh
