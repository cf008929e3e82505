// -check on surfaces: each connected part of the surface elements with its Euler
// characteristic, genus, boundary loops and defects.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "command_fixture.h"

namespace fs = std::filesystem;

namespace geomesh {
namespace {

class SurfaceCheck : public CommandTest {
 protected:
  SurfaceCheck() : CommandTest("surface-check-") {}
  bool said(const std::string& text) const { return err_.str().find(text) != std::string::npos; }
};

// A tetrahedron's faces as ASCII STL, `faces` of them (3: one face missing); with `flipLast`,
// the last face runs the wrong way.
std::string tetrahedronStl(int faces, bool flipLast) {
  const char* p[] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1"};
  std::vector<std::array<int, 3>> f = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  f.resize(std::size_t(faces));
  if (flipLast) std::swap(f.back()[1], f.back()[2]);
  std::string text = "solid t\n";
  for (const auto& t : f) {
    text += "facet normal 0 0 0\nouter loop\n";
    for (int v : t) text += std::string("vertex ") + p[v] + "\n";
    text += "endloop\nendfacet\n";
  }
  return text + "endsolid t\n";
}

TEST_F(SurfaceCheck, EachConnectedSurfaceGetsItsTopology) {
  const fs::path geo = write("two.geo", R"(SetFactory("OpenCASCADE");
Torus(1) = {0, 0, 0, 1, 0.3};
Sphere(2) = {5, 0, 0, 1};
Mesh.MeshSizeMax = 0.3;
)");
  ASSERT_EQ(run({geo.string(), "-2", "-check", "-o", (dir_ / "two.msh").string()}), 0)
      << err_.str();
  EXPECT_TRUE(said("triangles, Euler characteristic 0, genus 1, 0 boundary loops, 0 "
                   "non-manifold edges, 0 inconsistently oriented edges"))
      << err_.str();
  EXPECT_TRUE(said("triangles, Euler characteristic 2, genus 0, 0 boundary loops, 0 "
                   "non-manifold edges, 0 inconsistently oriented edges"))
      << err_.str();
  EXPECT_TRUE(said("Check: surface part 1 of 2: ")) << err_.str();
  EXPECT_TRUE(said("Check: surface part 2 of 2: ")) << err_.str();
}

TEST_F(SurfaceCheck, HolesAndTurnedFacetsOfAnStlAreCounted) {
  const fs::path open = write("open.stl", tetrahedronStl(3, false));
  EXPECT_EQ(run({open.string(), "-check"}), 0) << err_.str();
  EXPECT_TRUE(said("Check: surface part 1 of 1: 3 triangles, Euler characteristic 1, genus 0, "
                   "1 boundary loops, 0 non-manifold edges, 0 inconsistently oriented edges"))
      << err_.str();
  EXPECT_TRUE(said("3 boundary edges (on one facet only: holes or open borders), the first on "
                   "facet 1 at (0, 0, 0)"))
      << err_.str();
  const fs::path turned = write("turned.stl", tetrahedronStl(4, true));
  EXPECT_EQ(run({turned.string(), "-check"}), 0) << err_.str();
  EXPECT_TRUE(said("Check: surface part 1 of 1: 4 triangles, Euler characteristic 2, genus 0, "
                   "0 boundary loops, 0 non-manifold edges, 3 inconsistently oriented edges"))
      << err_.str();
}

TEST_F(SurfaceCheck, SurfacesThatCrossEachOtherAreTold) {
  // Two boxes of OpenCASCADE overlapping without a Boolean: their skins cross.
  const fs::path geo = write("boxes.geo", R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {0.5, 0.5, 0.5, 1, 1, 1};
Mesh.MeshSizeMax = 0.3;
)");
  run({geo.string(), "-2", "-check", "-o", (dir_ / "boxes.msh").string()});
  EXPECT_TRUE(
      said(" pairs of surface triangles cross each other (sharing no node), the first at ("))
      << err_.str();
  const fs::path apart = write("apart.geo", R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {3, 0, 0, 1, 1, 1};
Mesh.MeshSizeMax = 0.3;
)");
  run({apart.string(), "-2", "-check", "-o", (dir_ / "apart.msh").string()});
  EXPECT_FALSE(said("cross each other")) << err_.str();
}

TEST_F(SurfaceCheck, AScriptIsCheckedAfterMeshing) {
  const fs::path geo = write("sq.geo", R"(Point(1) = {0, 0, 0, 0.25};
Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 1, 0, 0.25};
Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
)");
  EXPECT_EQ(run({geo.string(), "-2", "-check", "-o", (dir_ / "sq.msh").string()}), 0)
      << err_.str();
  EXPECT_TRUE(said("triangles, Euler characteristic 1, genus 0, 1 boundary loops, 0 "
                   "non-manifold edges, 0 inconsistently oriented edges"))
      << err_.str();
  EXPECT_EQ(run({geo.string(), "-check"}), 0) << err_.str();
  EXPECT_TRUE(said("Check: no surface triangles")) << err_.str();
}

}  // namespace
}  // namespace geomesh
