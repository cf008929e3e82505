// checkMesh and the quality measures on meshes of order 2 to 4: valid meshes pass, and each
// defect of a high-order mesh (edge nodes that differ, inverted elements, open faces) shows.
#include "mesh/checks/mesh_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "io/msh_reader.h"
#include "io/msh_writer.h"
#include "kernel/geo/geo_factory.h"
#include "mesh/core/quality.h"
#include "mesh/high_order/reference_element.h"
#include "mesh/pipeline/generate.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;

// Raises every element to order `p` with the types that have nodes on edges only (Triangle9,
// Quad12, Tet16, ..., complete lines), placed straight between the corners. Each edge node is
// made once, held by the first entity in (dim, tag) order whose elements use that edge (the
// lowest-dimensional one, as a mesher classifies it), without parametric coordinates.
void raiseOrder(Mesh& mesh, int p) {
  std::map<std::tuple<NodeIndex, NodeIndex, int>, NodeIndex> made;  // (low, high, steps from low)
  std::vector<EntityId> ids;
  for (const auto& [id, em] : mesh.entities()) ids.push_back(id);
  for (EntityId id : ids) {
    EntityMesh& em = mesh.entity(id);
    std::vector<ElementBlock> raised;
    for (const ElementBlock& block : em.blocks) {
      if (family(block.type) == ElementFamily::Point) {
        raised.push_back(block);
        continue;
      }
      ElementBlock out{*elementTypeOf(family(block.type), p, true), {}};
      const std::vector<NodePlace>& places = referenceElement(out.type).places;
      for (std::size_t e = 0; e < block.size(); ++e) {
        const auto n = block.element(e);
        for (const NodePlace& place : places) {
          if (place.kind == NodePlace::Vertex) {
            out.nodes.push_back(n[place.corners[0]]);
            continue;
          }
          const NodeIndex a = n[place.corners[0]], b = n[place.corners[1]];
          const int steps = a < b ? place.weights[1] : place.weights[0];
          const auto key = std::make_tuple(std::min(a, b), std::max(a, b), steps);
          auto it = made.find(key);
          if (it == made.end()) {
            const Vec3 x = (place.weights[0] * mesh.node(a) + place.weights[1] * mesh.node(b)) /
                           static_cast<double>(place.total);
            it = made.emplace(key, mesh.addNode(x)).first;
            em.nodes.push_back(it->second);
          }
          out.nodes.push_back(it->second);
        }
      }
      raised.push_back(std::move(out));
    }
    em.blocks = std::move(raised);
  }
}

// The element `n` of `type` with its corners renumbered (new corner c is old corner
// corners[c]), each node inside an edge moved with its edge: for a mirror image, an inverted
// element with the same edges.
std::vector<NodeIndex> mirrored(ElementType type, std::span<const NodeIndex> n,
                                const std::vector<int>& corners) {
  const std::vector<NodePlace>& places = referenceElement(type).places;
  auto old = [&](int c) { return corners[c]; };
  std::vector<NodeIndex> out;
  for (const NodePlace& place : places) {
    if (place.kind == NodePlace::Vertex) {
      out.push_back(n[old(place.corners[0])]);
      continue;
    }
    const int a = old(place.corners[0]), b = old(place.corners[1]);
    for (std::size_t k = 0; k < places.size(); ++k) {
      const NodePlace& q = places[k];
      if (q.kind != NodePlace::Edge) continue;
      if ((q.corners[0] == a && q.corners[1] == b && q.weights[0] == place.weights[0]) ||
          (q.corners[0] == b && q.corners[1] == a && q.weights[1] == place.weights[0]))
        out.push_back(n[k]);
    }
  }
  return out;
}

bool reports(const MeshCheckReport& r, const std::string& text) {
  return r.summary().find(text) != std::string::npos;
}

struct Meshed {
  Model model;
  Mesh mesh;
};

Meshed triangulatedSquare() {
  PolygonModelBuilder builder;
  builder.surface({builder.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25)});
  Meshed m{std::move(builder.model), {}};
  SilentSink log;
  generateMesh(m.model, {}, 2, m.mesh, log);
  return m;
}

// The unit cube swept from the unit square in 3 layers: hexahedra when `recombine` (the square
// made of quadrangles), else prisms; tetrahedra when `tetrahedra`.
Meshed sweptCube(bool recombine, bool tetrahedra = false) {
  GeoFactory geo;
  for (int k = 0; k < 4; ++k)
    geo.addPoint(k + 1, {double(k == 1 || k == 2), double(k >= 2), 0}, 0.34);
  for (int k = 1; k <= 4; ++k) geo.addLine(k, k, k % 4 + 1);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {1});
  geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}),
              ExtrusionLayers{{3}, {1}, !tetrahedra});
  Meshed m;
  geo.synchronize(m.model);
  m.model.meshConstraints().transfiniteSurfaces[1] = TransfiniteSurface{};
  if (recombine) m.model.meshConstraints().recombinedSurfaces[1] = 45;
  SilentSink log;
  generateMesh(m.model, {}, 3, m.mesh, log);
  return m;
}

ElementBlock& firstBlockOfDimension(Mesh& mesh, int dim) {
  for (const auto& [id, em] : mesh.entities())
    if (id.dim == dim)
      for (ElementBlock& b : mesh.entity(id).blocks)
        if (b.size() > 0) return b;
  throw std::logic_error("no elements");
}

TEST(MeshCheckHighOrder, RaisedTriangleMeshesAreValidAtEveryOrder) {
  for (int p = 2; p <= 4; ++p) {
    Meshed m = triangulatedSquare();
    raiseOrder(m.mesh, p);
    ASSERT_EQ(order(m.mesh.find({2, 1})->blocks.front().type), p);
    const MeshCheckReport r = checkMesh(m.model, m.mesh);
    EXPECT_TRUE(r.ok()) << "order " << p << ":\n" << r.summary();
  }
}

TEST(MeshCheckHighOrder, RaisedVolumeMeshesAreValid) {
  const struct {
    bool recombine, tetrahedra;
    int maxOrder;
    ElementFamily family;
  } cases[] = {{true, false, 4, ElementFamily::Hex},
               {false, false, 2, ElementFamily::Prism},
               {false, true, 4, ElementFamily::Tet}};
  for (const auto& c : cases)
    for (int p = 2; p <= c.maxOrder; ++p) {
      Meshed m = sweptCube(c.recombine, c.tetrahedra);
      raiseOrder(m.mesh, p);
      const ElementBlock& volume = firstBlockOfDimension(m.mesh, 3);
      ASSERT_EQ(family(volume.type), c.family);
      ASSERT_EQ(order(volume.type), p);
      const MeshCheckReport r = checkMesh(m.model, m.mesh);
      EXPECT_TRUE(r.ok()) << elementName(volume.type) << ":\n" << r.summary();
    }
}

TEST(MeshCheckHighOrder, DifferentNodesInsideASharedEdgeAreReported) {
  Meshed m = triangulatedSquare();
  raiseOrder(m.mesh, 2);
  EntityMesh& surface = m.mesh.entity({2, 1});
  ElementBlock& triangles = surface.blocks.front();
  // A second node where the first triangle's node inside its edge 1-2 is, used by it alone.
  const NodeIndex copy = m.mesh.addNode(m.mesh.node(triangles.nodes[4]) + Vec3{1e-3, 0, 0});
  surface.nodes.push_back(copy);
  triangles.nodes[4] = copy;
  const MeshCheckReport r = checkMesh(m.model, m.mesh);
  EXPECT_TRUE(reports(r, "inside it in one element and")) << r.summary();
}

TEST(MeshCheckHighOrder, FirstOrderCurveBesideSecondOrderTrianglesIsReported) {
  Meshed m = triangulatedSquare();
  raiseOrder(m.mesh, 2);
  ElementBlock& lines = m.mesh.entity({1, 1}).blocks.front();
  ASSERT_EQ(lines.type, ElementType::Line3);
  ElementBlock linear{ElementType::Line2, {}};
  for (std::size_t e = 0; e < lines.size(); ++e)
    linear.nodes.insert(linear.nodes.end(), {lines.element(e)[0], lines.element(e)[1]});
  lines = linear;
  const MeshCheckReport r = checkMesh(m.model, m.mesh);
  EXPECT_TRUE(reports(r, "inside it in one element and ()") ||
              reports(r, "() inside it in one element"))
      << r.summary();
}

TEST(MeshCheckHighOrder, ReversedEdgesAgreeWithTheirNeighbours) {
  // The lines of a curve run along it; the triangles on its left run the other way along the
  // same edges: same nodes inside, in reverse order (order 4: three of them).
  Meshed m = triangulatedSquare();
  raiseOrder(m.mesh, 4);
  ElementBlock& lines = m.mesh.entity({1, 2}).blocks.front();
  const ElementBlock before = lines;
  for (std::size_t e = 0; e < lines.size(); ++e) {
    NodeIndex* n = lines.nodes.data() + e * 5;
    std::swap(n[2], n[4]);  // nodes inside from the end, not the start
  }
  EXPECT_FALSE(checkMesh(m.model, m.mesh).ok());
  lines = before;
  EXPECT_TRUE(checkMesh(m.model, m.mesh).ok());
}

TEST(MeshCheckHighOrder, InvertedHighOrderTriangleIsReportedOnItsCorners) {
  Meshed m = triangulatedSquare();
  raiseOrder(m.mesh, 3);
  ElementBlock& triangles = m.mesh.entity({2, 1}).blocks.front();
  const std::vector<NodeIndex> flipped = mirrored(triangles.type, triangles.element(0), {0, 2, 1});
  std::copy(flipped.begin(), flipped.end(), triangles.nodes.begin());
  const MeshCheckReport r = checkMesh(m.model, m.mesh);
  EXPECT_TRUE(reports(r, "triangle 1 is inverted")) << r.summary();
  EXPECT_FALSE(reports(r, "inside it")) << r.summary();  // the mirror keeps its edges
}

TEST(MeshCheckHighOrder, InvertedHighOrderVolumeElementsAreReported) {
  for (bool recombine : {true, false}) {
    Meshed m = sweptCube(recombine, !recombine);
    raiseOrder(m.mesh, 2);
    ElementBlock& volume = firstBlockOfDimension(m.mesh, 3);
    const std::vector<NodeIndex> flipped =
        recombine ? mirrored(volume.type, volume.element(0), {0, 3, 2, 1, 4, 7, 6, 5})
                  : mirrored(volume.type, volume.element(0), {0, 2, 1, 3});
    ASSERT_EQ(flipped.size(), volume.element(0).size());
    std::copy(flipped.begin(), flipped.end(), volume.nodes.begin());
    const MeshCheckReport r = checkMesh(m.model, m.mesh);
    EXPECT_TRUE(reports(r, "non-positive Jacobian")) << elementName(volume.type) << r.summary();
    EXPECT_FALSE(reports(r, "inside it")) << r.summary();
  }
}

TEST(MeshCheckHighOrder, MissingHexahedronOpensTheVolume) {
  Meshed m = sweptCube(true);
  raiseOrder(m.mesh, 2);
  ElementBlock& hexes = firstBlockOfDimension(m.mesh, 3);
  ASSERT_EQ(hexes.type, ElementType::Hex20);
  hexes.nodes.resize(hexes.nodes.size() - 20);
  const MeshCheckReport r = checkMesh(m.model, m.mesh);
  EXPECT_TRUE(reports(r, "shared by")) << r.summary();
}

TEST(MeshCheckHighOrder, HighOrderMeshReadFromMshIsValid) {
  for (double version : {4.1, 2.2}) {
    Meshed m = sweptCube(true);
    raiseOrder(m.mesh, 3);
    std::ostringstream out;
    writeMsh(out, m.model, m.mesh, {true, true, version});
    std::istringstream in(out.str());
    Model model;
    Mesh mesh;
    readMsh(in, model, mesh, "raised.msh");
    const MeshCheckReport r = checkMesh(model, mesh);
    EXPECT_TRUE(r.ok()) << version << ":\n" << r.summary();
  }
}

TEST(MeshCheckHighOrder, QualityAndMeasuresUseTheCorners) {
  Meshed linear = triangulatedSquare();
  Meshed raised = triangulatedSquare();
  raiseOrder(raised.mesh, 2);
  for (QualityMeasure q : {QualityMeasure::Gamma, QualityMeasure::Sicn}) {
    const QualityStats a = meshQuality(linear.mesh, 2, q), b = meshQuality(raised.mesh, 2, q);
    EXPECT_EQ(a.count, b.count);
    EXPECT_GT(b.count, 0u);
    EXPECT_DOUBLE_EQ(a.min, b.min);
    EXPECT_DOUBLE_EQ(a.mean, b.mean);
  }
  for (bool recombine : {true, false}) {
    Meshed cube = sweptCube(recombine, !recombine);
    raiseOrder(cube.mesh, 2);
    const std::size_t tetrahedra = meshQuality(cube.mesh, 3, QualityMeasure::Gamma).count;
    EXPECT_EQ(tetrahedra > 0, !recombine);
    double volume = 0;
    for (const auto& [id, em] : cube.mesh.entities())
      for (const ElementBlock& b : em.blocks)
        if (dimension(b.type) == 3)
          for (std::size_t e = 0; e < b.size(); ++e)
            volume += elementMeasure(cube.mesh, b.type, b.element(e));
    EXPECT_NEAR(volume, 1.0, 1e-9) << (recombine ? "hexahedra" : "tetrahedra");
  }
}

}  // namespace
}  // namespace geomesh
