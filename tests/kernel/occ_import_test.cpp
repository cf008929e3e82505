// The OpenCASCADE factory's CAD files: what it writes, it reads back with the same shapes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

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

// An XAO file geomesh writes gives every entity its tag back, gaps and free points included;
// one without tags (the reference's) numbers them as a BREP file would.
TEST(OccImport, XaoKeepsTags) {
  OccFactory occ = boxAndBall();
  occ.addPoint(100, {7, 7, 7}, 0);
  const std::string path = scratch::path("occ-tags.xao");
  occ.exportShapes(path);
  OccFactory read;
  const std::vector<EntityId> top = read.importShapes(path, true);
  EXPECT_EQ(top, (std::vector<EntityId>{{3, 1}, {3, 2}}));
  for (int dim = 0; dim <= 3; ++dim) EXPECT_EQ(read.tags(dim), occ.tags(dim)) << dim;
  for (int p : occ.tags(0)) {
    const Vec3 a = occ.pointCoordinates(p), b = read.pointCoordinates(p);
    EXPECT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z) << "point " << p;
  }
  EXPECT_NEAR(read.volume(2), 4 * std::numbers::pi / 3, 1e-6);
  // Tags already taken: the shapes get new ones instead.
  const std::vector<EntityId> again = read.importShapes(path, true);
  EXPECT_EQ(again, (std::vector<EntityId>{{3, 3}, {3, 4}}));
  std::filesystem::remove(path);
}

TEST(OccImport, XaoWithoutTagsIsNumberedAsItsShape) {
  const std::string path = scratch::path("occ-untagged.xao");
  boxAndBall().exportShapes(path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string xao = text.str();
  for (std::size_t at = xao.find(" tag=\""); at != std::string::npos; at = xao.find(" tag=\""))
    xao.erase(at, xao.find('"', at + 6) + 1 - at);
  in.close();
  std::ofstream(path) << xao;
  OccFactory read;
  read.addBox(7, {20, 0, 0}, {1, 1, 1});
  EXPECT_EQ(read.importShapes(path, true), (std::vector<EntityId>{{3, 8}, {3, 9}}));
  EXPECT_EQ(read.tags(2).size(), 6u + 6u + 1u + 1u);  // the free rectangle too
  std::filesystem::remove(path);
}

TEST(OccImport, NotAnXaoFile) {
  const std::string path = scratch::path("occ-bad.xao");
  std::ofstream(path) << "<XAO><geometry/></XAO>\n";
  OccFactory occ;
  EXPECT_THROW(occ.importShapes(path), GeometryError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace geomesh
