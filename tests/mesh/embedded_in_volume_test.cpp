// Points, curves and surfaces embedded in a volume: its tetrahedra conform to their meshes, in
// both kernels; crossings are errors naming the entities; the mesh check sees non-conformity.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "kernel/geo/geo_factory.h"
#include "kernel/occ/occ_factory.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/core/mesh_error.h"
#include "mesh/core/predicates.h"
#include "mesh/pipeline/generate.h"
#include "mesh/volumes/tet_optimizer.h"
#include "mesh_measures.h"

namespace geomesh {
namespace {

using testing::QuietSink;
using testing::totalVolume;

// The unit cube as the built-in kernel makes it: points 1-8 of size h, surfaces 1-6, volume 1.
void addUnitCube(GeoFactory& geo, double h) {
  for (int k = 0; k < 8; ++k)
    geo.addPoint(k + 1, {double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)}, h);
  // Each face by its corners, in order around it.
  const int faces[6][4] = {{1, 2, 4, 3}, {5, 6, 8, 7}, {1, 2, 6, 5},
                           {3, 4, 8, 7}, {1, 3, 7, 5}, {2, 4, 8, 6}};
  std::map<std::pair<int, int>, int> lines;
  int nextLine = 1;
  for (int f = 0; f < 6; ++f) {
    std::vector<int> loop;
    for (int k = 0; k < 4; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 4];
      auto it = lines.find({std::min(a, b), std::max(a, b)});
      if (it == lines.end()) {
        geo.addLine(nextLine, std::min(a, b), std::max(a, b));
        it = lines.emplace(std::pair{std::min(a, b), std::max(a, b)}, nextLine++).first;
      }
      loop.push_back(a < b ? it->second : -it->second);
    }
    geo.addCurveLoop(f + 1, loop);
    geo.addPlaneSurface(f + 1, {f + 1});
  }
  geo.addSurfaceLoop(1, {1, 2, 3, 4, 5, 6});
  geo.addVolume(1, {1});
}

// The square [lo, hi]^2 at height z: points 101-104 of size h, lines 101-104, surface 101.
void addSquare(GeoFactory& geo, double lo, double hi, double z, double h) {
  geo.addPoint(101, {lo, lo, z}, h);
  geo.addPoint(102, {hi, lo, z}, h);
  geo.addPoint(103, {hi, hi, z}, h);
  geo.addPoint(104, {lo, hi, z}, h);
  for (int k = 0; k < 4; ++k) geo.addLine(101 + k, 101 + k, 101 + (k + 1) % 4);
  geo.addCurveLoop(101, {101, 102, 103, 104});
  geo.addPlaneSurface(101, {101});
}

struct Meshed {
  Model model;
  Mesh mesh;
};

Meshed mesh3d(const GeometryFactory& factory, double sizeMax) {
  Meshed m;
  factory.synchronize(m.model);
  MeshOptions options;
  options.sizeMax = sizeMax;
  QuietSink log;
  generateMesh(m.model, options, 3, m.mesh, log);
  return m;
}

const ElementBlock& tetsOf(const Mesh& mesh) {
  return *mesh.find({3, 1})->findBlock(ElementType::Tet4);
}

// Every triangle of the surface is a face of exactly two tetrahedra, whose fourth nodes lie on
// opposite sides of it.
void expectTwoSidedFaces(const Mesh& mesh, int surface) {
  using Face = std::array<NodeIndex, 3>;
  std::map<Face, std::vector<NodeIndex>> apexes;
  const ElementBlock& tets = tetsOf(mesh);
  for (std::size_t e = 0; e < tets.size(); ++e) {
    const auto t = tets.element(e);
    for (int k = 0; k < 4; ++k) {
      Face f{t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]};
      std::sort(f.begin(), f.end());
      apexes[f].push_back(t[k]);
    }
  }
  const ElementBlock* tris = mesh.find({2, surface})->findBlock(ElementType::Triangle3);
  ASSERT_NE(tris, nullptr);
  ASSERT_GT(tris->size(), 8u);
  for (std::size_t e = 0; e < tris->size(); ++e) {
    const auto t = tris->element(e);
    Face f{t[0], t[1], t[2]};
    std::sort(f.begin(), f.end());
    const std::vector<NodeIndex>& sides = apexes[f];
    ASSERT_EQ(sides.size(), 2u) << "triangle " << e << " of surface " << surface;
    const Vec3 a = mesh.node(t[0]), b = mesh.node(t[1]), c = mesh.node(t[2]);
    EXPECT_LT(orient3d(a, b, c, mesh.node(sides[0])) * orient3d(a, b, c, mesh.node(sides[1])), 0)
        << "triangle " << e << " of surface " << surface;
  }
}

std::set<std::pair<NodeIndex, NodeIndex>> tetEdges(const Mesh& mesh) {
  std::set<std::pair<NodeIndex, NodeIndex>> edges;
  const ElementBlock& tets = tetsOf(mesh);
  for (std::size_t e = 0; e < tets.size(); ++e) {
    const auto t = tets.element(e);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.insert(std::minmax(t[i], t[j]));
  }
  return edges;
}

bool isTetNode(const Mesh& mesh, NodeIndex n) {
  const ElementBlock& tets = tetsOf(mesh);
  return std::find(tets.nodes.begin(), tets.nodes.end(), n) != tets.nodes.end();
}

void expectValid(const Meshed& m) {
  const MeshCheckReport report = checkMesh(m.model, m.mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_NEAR(totalVolume(m.mesh), 1, 1e-12);
}

TEST(EmbeddedInVolume, OccSquareInCubeIsMeshedIntoTheTetrahedra) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addRectangle(10, {0.25, 0.25, 0.5}, 0.5, 0.5);
  occ.embed(2, {10}, 3, 1);
  occ.setMeshSize({9, 10, 11, 12}, 0.05);
  const Meshed m = mesh3d(occ, 0.2);
  expectValid(m);
  expectTwoSidedFaces(m.mesh, 10);
  // The square's fine size spreads into the volume: more nodes than the cube alone would get.
  OccFactory alone;
  alone.addBox(1, {0, 0, 0}, {1, 1, 1});
  const Meshed cube = mesh3d(alone, 0.2);
  EXPECT_GT(m.mesh.find({3, 1})->nodes.size(), 2 * cube.mesh.find({3, 1})->nodes.size());
}

TEST(EmbeddedInVolume, BuiltInSquareInCubeIsMeshedIntoTheTetrahedra) {
  GeoFactory geo;
  addUnitCube(geo, 0.25);
  addSquare(geo, 0.2, 0.7, 0.4, 0.05);
  geo.embed(2, {101}, 3, 1);
  const Meshed m = mesh3d(geo, 1e22);
  expectValid(m);
  expectTwoSidedFaces(m.mesh, 101);
}

TEST(EmbeddedInVolume, CurveAndPointsAreEdgesAndNodesOfTheTetrahedra) {
  GeoFactory geo;
  addUnitCube(geo, 0.2);
  geo.addPoint(101, {0.5, 0.5, 0.2}, 0.02);
  geo.addPoint(102, {0.4, 0.6, 0.8}, 0.02);
  geo.addLine(101, 101, 102);
  geo.addPoint(103, {0.3, 0.7, 0.5}, 0.03);
  geo.addPoint(104, {0.75, 0.25, 0.5}, 0.03);
  geo.embed(1, {101}, 3, 1);
  geo.embed(0, {103, 104}, 3, 1);
  const Meshed m = mesh3d(geo, 1e22);
  expectValid(m);
  const auto edges = tetEdges(m.mesh);
  const ElementBlock* lines = m.mesh.find({1, 101})->findBlock(ElementType::Line2);
  ASSERT_GT(lines->size(), 20u);
  for (std::size_t e = 0; e < lines->size(); ++e)
    EXPECT_TRUE(edges.contains(std::minmax(lines->element(e)[0], lines->element(e)[1])))
        << "segment " << e;
  for (int p : {101, 102, 103, 104})
    EXPECT_TRUE(isTetNode(m.mesh, m.mesh.find({0, p})->nodes.front())) << "point " << p;
}

// As the reference, the fine sizes of embedded curves and points do not refine the tetrahedra
// around them (embedded surfaces' do).
TEST(EmbeddedInVolume, CurveSizesStayOnTheCurve) {
  GeoFactory alone;
  addUnitCube(alone, 0.2);
  const std::size_t plain = mesh3d(alone, 1e22).mesh.nodeCount();
  GeoFactory geo;
  addUnitCube(geo, 0.2);
  geo.addPoint(101, {0.5, 0.5, 0.2}, 0.02);
  geo.addPoint(102, {0.4, 0.6, 0.8}, 0.02);
  geo.addLine(101, 101, 102);
  geo.embed(1, {101}, 3, 1);
  const Meshed m = mesh3d(geo, 1e22);
  const std::size_t curveNodes = m.mesh.find({1, 101})->nodes.size() + 2;
  EXPECT_LT(m.mesh.nodeCount(), 1.3 * plain + curveNodes);
}

// Five nodes: an equilateral triangle p, q, r around the z axis, and d, e on the axis at
// heights h and -h; tetrahedra either side of the triangle (two), or around the edge de (three).
Mesh fiveNodes(double h, bool aroundEdge) {
  Mesh mesh;
  const double s = std::sqrt(3.0) / 2;
  for (Vec3 x : {Vec3{1, 0, 0}, Vec3{-0.5, s, 0}, Vec3{-0.5, -s, 0}, Vec3{0, 0, h}, Vec3{0, 0, -h}})
    mesh.addNode(x);
  ElementBlock& tets = mesh.entity({3, 1}).block(ElementType::Tet4);
  if (aroundEdge)
    tets.nodes = {0, 1, 4, 3, 1, 2, 4, 3, 2, 0, 4, 3};
  else
    tets.nodes = {0, 1, 2, 3, 0, 2, 1, 4};
  return mesh;
}

// The optimizer keeps the faces and edges it is told to, where a flip would raise the quality.
TEST(EmbeddedInVolume, OptimizerKeepsEmbeddedFacesAndEdges) {
  Mesh flat = fiveNodes(0.15, false);
  EXPECT_EQ(optimizeTetrahedra(flat, {3, 1}, 1.0).faceSwaps, 1u);  // the face goes
  Mesh keptFace = fiveNodes(0.15, false);
  const TetOptimizerStats face = optimizeTetrahedra(keptFace, {3, 1}, 1.0, {{{0, 1, 2}}, {}});
  EXPECT_EQ(face.faceSwaps + face.edgeRemovals, 0u);
  Mesh tall = fiveNodes(1.5, true);
  EXPECT_EQ(optimizeTetrahedra(tall, {3, 1}, 1.0).edgeRemovals, 1u);  // the edge goes
  Mesh keptEdge = fiveNodes(1.5, true);
  const TetOptimizerStats edge = optimizeTetrahedra(keptEdge, {3, 1}, 1.0, {{}, {{3, 4}}});
  EXPECT_EQ(edge.faceSwaps + edge.edgeRemovals, 0u);
}

// Meshes the model in 3D and returns the message of the MeshError it throws.
std::string meshError(const GeometryFactory& factory) {
  Model model;
  factory.synchronize(model);
  Mesh mesh;
  QuietSink log;
  try {
    generateMesh(model, MeshOptions{}, 3, mesh, log);
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity, (EntityId{3, 1}));
    return e.what();
  }
  ADD_FAILURE() << "no MeshError";
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(EmbeddedInVolume, SurfaceCrossingTheBoundaryIsAnError) {
  GeoFactory geo;
  addUnitCube(geo, 0.25);
  addSquare(geo, 0.5, 1.5, 0.5, 0.25);
  geo.embed(2, {101}, 3, 1);
  const std::string what = meshError(geo);
  EXPECT_TRUE(contains(what, "embedded surface 101 crosses boundary surface")) << what;
}

TEST(EmbeddedInVolume, CurveCrossingAnEmbeddedSurfaceIsAnError) {
  GeoFactory geo;
  addUnitCube(geo, 0.25);
  addSquare(geo, 0.25, 0.75, 0.5, 0.1);
  geo.addPoint(201, {0.45, 0.55, 0.2}, 0.1);
  geo.addPoint(202, {0.55, 0.45, 0.8}, 0.1);
  geo.addLine(201, 201, 202);
  geo.embed(2, {101}, 3, 1);
  geo.embed(1, {201}, 3, 1);
  const std::string what = meshError(geo);
  EXPECT_TRUE(contains(what, "embedded curve 201 crosses embedded surface 101")) << what;
}

TEST(EmbeddedInVolume, CurvesCrossingEachOtherAreAnError) {
  GeoFactory geo;
  addUnitCube(geo, 0.25);
  geo.addPoint(201, {0.2, 0.5, 0.5}, 0.1);
  geo.addPoint(202, {0.8, 0.5, 0.5}, 0.1);
  geo.addPoint(203, {0.5, 0.2, 0.5}, 0.1);
  geo.addPoint(204, {0.5, 0.8, 0.5}, 0.1);
  geo.addLine(201, 201, 202);
  geo.addLine(202, 203, 204);
  geo.embed(1, {201, 202}, 3, 1);
  const std::string what = meshError(geo);
  EXPECT_TRUE(contains(what, "embedded curve 202 crosses embedded curve 201")) << what;
}

TEST(EmbeddedInVolume, PointOnAnEmbeddedSurfaceIsAnError) {
  GeoFactory geo;
  addUnitCube(geo, 0.25);
  addSquare(geo, 0.25, 0.75, 0.5, 0.1);
  geo.addPoint(201, {0.4, 0.45, 0.5}, 0.1);
  geo.embed(2, {101}, 3, 1);
  geo.embed(0, {201}, 3, 1);
  const std::string what = meshError(geo);
  EXPECT_TRUE(contains(what, "embedded point 201 lies on embedded surface 101")) << what;
}

TEST(EmbeddedInVolume, PointOutsideTheVolumeIsAnError) {
  GeoFactory geo;
  addUnitCube(geo, 0.25);
  geo.addPoint(201, {1.5, 0.5, 0.5}, 0.1);
  geo.embed(0, {201}, 3, 1);
  const std::string what = meshError(geo);
  EXPECT_TRUE(contains(what, "embedded point 201 lies outside the volume")) << what;
}

// The mesh check knows what a volume's tetrahedra must conform to: the same mesh, made without
// the embedding, fails it once the model embeds the square.
TEST(EmbeddedInVolume, MeshCheckReportsTetrahedraIgnoringAnEmbeddedSurface) {
  GeoFactory geo;
  addUnitCube(geo, 0.25);
  addSquare(geo, 0.25, 0.75, 0.5, 0.1);
  Meshed m = mesh3d(geo, 1e22);
  ASSERT_TRUE(checkMesh(m.model, m.mesh).ok());
  geo.embed(2, {101}, 3, 1);
  Model embedding;
  geo.synchronize(embedding);
  const MeshCheckReport report = checkMesh(embedding, m.mesh);
  ASSERT_FALSE(report.ok());
  EXPECT_TRUE(contains(report.summary(), "volume 1: embedded surface 101: triangle"))
      << report.summary();
}

}  // namespace
}  // namespace geomesh
