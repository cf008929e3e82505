// Partitioning: METIS and slices give every top element one partition; the pieces place every
// node and element once, separate partitions by interface pieces, and bound each other.
#include "mesh/partition/partition_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>

#include "mesh/high_order/reference_element.h"
#include "mesh/partition/partition_sets.h"
#include "mesh/pipeline/generate.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

Mesh squareMesh(Model& model, double h) {
  testing::PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h)});
  model = std::move(b.model);
  Mesh mesh;
  SilentSink log;
  generateMesh(model, {}, 2, mesh, log);
  return mesh;
}

PartitionSettings settings(int count) {
  PartitionSettings s;
  s.count = count;
  return s;
}

std::map<int, std::size_t> topLoad(const MeshPartitions& partitions, int dim) {
  std::map<int, std::size_t> load;
  for (const PartitionEntity& piece : partitions.entities)
    for (const ElementBlock& b : piece.blocks)
      if (dimension(b.type) == dim) {
        EXPECT_EQ(piece.partitions.size(), 1u) << "top elements lie in one partition";
        load[piece.partitions.front()] += b.size();
      }
  return load;
}

TEST(Partition, EveryTriangleGoesToOneOfBalancedPartitions) {
  Model model;
  Mesh mesh = squareMesh(model, 0.04);
  partitionMesh(model, mesh, settings(3));
  ASSERT_NE(mesh.partitions(), nullptr);
  const std::map<int, std::size_t> load = topLoad(*mesh.partitions(), 2);
  ASSERT_EQ(load.size(), 3u);
  std::size_t total = 0;
  for (const auto& [p, n] : load) total += n;
  EXPECT_EQ(total, mesh.elementCount(2));
  for (const auto& [p, n] : load) EXPECT_LT(n, 1.03 * total / 3.0) << "partition " << p;
}

TEST(Partition, EveryNodeAndElementIsPlacedOnce) {
  Model model;
  Mesh mesh = squareMesh(model, 0.05);
  partitionMesh(model, mesh, settings(4));
  std::vector<int> placed(mesh.nodeCount(), 0);
  std::map<int, std::size_t> elements;  // by dimension, model elements only
  for (const PartitionEntity& piece : mesh.partitions()->entities) {
    for (NodeIndex n : piece.nodes) ++placed[n];
    if (piece.parent.dim == piece.id.dim)
      for (const ElementBlock& b : piece.blocks) elements[dimension(b.type)] += b.size();
  }
  EXPECT_TRUE(std::all_of(placed.begin(), placed.end(), [](int k) { return k == 1; }));
  for (int d = 0; d <= 2; ++d) EXPECT_EQ(elements[d], mesh.elementCount(d)) << "dimension " << d;
}

TEST(Partition, InterfaceLinesSeparateTrianglesOfTheirTwoPartitions) {
  Model model;
  Mesh mesh = squareMesh(model, 0.05);
  partitionMesh(model, mesh, settings(3));
  std::map<FacetKey, std::set<int>> sides;  // edge -> partitions of its triangles
  for (const PartitionEntity& piece : mesh.partitions()->entities)
    for (const ElementBlock& b : piece.blocks)
      if (dimension(b.type) == 2)
        for (std::size_t i = 0; i < b.size(); ++i)
          for (const std::vector<int>& edge : facetsOf(ElementFamily::Triangle))
            sides[facetKey(std::array<NodeIndex, 2>{b.element(i)[edge[0]], b.element(i)[edge[1]]})]
                .insert(piece.partitions.front());
  std::size_t interfaceLines = 0, cutEdges = 0;
  for (const auto& [edge, parts] : sides) cutEdges += parts.size() == 2;
  for (const PartitionEntity& piece : mesh.partitions()->entities) {
    if (piece.id.dim != 1 || piece.parent.dim != 2) continue;
    ASSERT_EQ(piece.partitions.size(), 2u);
    const ElementBlock& lines = piece.blocks.at(0);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const std::set<int>& parts = sides.at(facetKey(lines.element(i)));
      EXPECT_EQ(std::vector<int>(parts.begin(), parts.end()), piece.partitions);
      ++interfaceLines;
    }
  }
  EXPECT_GT(interfaceLines, 0u);
  EXPECT_EQ(interfaceLines, cutEdges) << "every edge between partitions is an interface line";
}

TEST(Partition, PiecesAreBoundedByLowerPiecesOfTheirPartitions) {
  Model model;
  Mesh mesh = squareMesh(model, 0.05);
  partitionMesh(model, mesh, settings(3));
  std::map<EntityId, const PartitionEntity*> byId;
  for (const PartitionEntity& piece : mesh.partitions()->entities) byId[piece.id] = &piece;
  for (const PartitionEntity& piece : mesh.partitions()->entities) {
    if (piece.id.dim == 0) continue;
    EXPECT_FALSE(piece.boundary.empty()) << "piece " << piece.id.dim << " " << piece.id.tag;
    if (piece.id.dim == 1) {  // a chain from its first point to its last: start, -end
      ASSERT_EQ(piece.boundary.size(), 2u);
      EXPECT_GT(piece.boundary[0], 0);
      EXPECT_LT(piece.boundary[1], 0);
    }
    for (int tag : piece.boundary) {
      const PartitionEntity* side = byId.at({piece.id.dim - 1, std::abs(tag)});
      EXPECT_TRUE(std::includes(side->partitions.begin(), side->partitions.end(),
                                piece.partitions.begin(), piece.partitions.end()));
    }
  }
  // Tags follow the model's: a surface piece is never tag 1, the model's surface.
  for (const PartitionEntity& piece : mesh.partitions()->entities)
    EXPECT_GT(piece.id.tag, model.maxTag(piece.id.dim));
}

TEST(Partition, TetrahedraOfACubeSplitWithInterfaceSurfaces) {
  const Model model = testing::cubeModel(0.2);
  Mesh mesh;
  SilentSink log;
  generateMesh(model, {}, 3, mesh, log);
  partitionMesh(model, mesh, settings(4));
  const std::map<int, std::size_t> load = topLoad(*mesh.partitions(), 3);
  ASSERT_EQ(load.size(), 4u);
  std::size_t interfaceTriangles = 0, points = 0;
  for (const PartitionEntity& piece : mesh.partitions()->entities) {
    if (piece.id.dim == 2 && piece.parent.dim == 3) {
      EXPECT_EQ(piece.partitions.size(), 2u);
      for (const ElementBlock& b : piece.blocks) interfaceTriangles += b.size();
    }
    points += piece.id.dim == 0;
  }
  EXPECT_GT(interfaceTriangles, 0u);
  EXPECT_GE(points, 8u);
  // Points hold one node; curves are single chains of lines, each starting where the last
  // one ended.
  for (const PartitionEntity& piece : mesh.partitions()->entities) {
    if (piece.id.dim == 0) {
      EXPECT_EQ(piece.nodes.size(), 1u);
    }
    if (piece.id.dim != 1) continue;
    ASSERT_EQ(piece.blocks.size(), 1u);
    const ElementBlock& chain = piece.blocks[0];
    for (std::size_t i = 1; i < chain.size(); ++i)
      EXPECT_EQ(chain.element(i)[0], chain.element(i - 1)[1]) << "curve piece " << piece.id.tag;
  }
}

TEST(Partition, FacetsOfCurvedElementsCarryTheirEdgeAndFaceNodes) {
  // Face 1 of a Tet10 has corners 0, 1, 3 (facetsOf); its Triangle6 takes the tetrahedron's
  // nodes on edges 0-1, 1-3 and 3-0, wherever the tetrahedron numbers them.
  const FacetNodes& face = facetNodes(ElementType::Tet10, 1);
  EXPECT_EQ(face.type, ElementType::Triangle6);
  ASSERT_EQ(face.nodes.size(), 6u);
  EXPECT_EQ(std::vector<int>(face.nodes.begin(), face.nodes.begin() + 3),
            (std::vector<int>{0, 1, 3}));
  const ReferenceElement& tet = referenceElement(ElementType::Tet10);
  for (int k = 3; k < 6; ++k) {
    const std::array<double, 3>& x = tet.xi[face.nodes[k]];
    const auto& a = tet.xi[face.nodes[k - 3]];
    const auto& b = tet.xi[face.nodes[(k - 2) % 3]];
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(x[c], (a[c] + b[c]) / 2) << "node " << k;
  }
  EXPECT_EQ(facetNodes(ElementType::Hex27, 0).type, ElementType::Quad9);
}

TEST(Partition, InterfacesOfASecondOrderMeshAreSecondOrder) {
  Model model;
  testing::PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  model = std::move(b.model);
  MeshOptions options;
  options.elementOrder = 2;
  Mesh mesh;
  SilentSink log;
  generateMesh(model, options, 2, mesh, log);
  partitionMesh(model, mesh, settings(2));
  std::size_t lines = 0;
  for (const PartitionEntity& piece : mesh.partitions()->entities)
    if (piece.id.dim == 1 && piece.parent.dim == 2)
      for (const ElementBlock& block : piece.blocks) {
        EXPECT_EQ(block.type, ElementType::Line3);
        for (std::size_t i = 0; i < block.size(); ++i, ++lines) {
          const auto line = block.element(i);
          const Vec3 a = mesh.node(line[0]), c = mesh.node(line[1]), m = mesh.node(line[2]);
          EXPECT_NEAR(norm(m - 0.5 * (a + c)), 0, 1e-12);  // straight edges of a plane
        }
      }
  EXPECT_GT(lines, 0u);
}

TEST(Partition, IsDeterministic) {
  Model model;
  Mesh first = squareMesh(model, 0.05);
  Mesh second = first;
  partitionMesh(model, first, settings(5));
  partitionMesh(model, second, settings(5));
  const auto& a = first.partitions()->entities;
  const auto& b = second.partitions()->entities;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, b[i].id);
    EXPECT_EQ(a[i].nodes, b[i].nodes);
    EXPECT_EQ(a[i].partitions, b[i].partitions);
  }
}

TEST(Partition, MorePartitionsThanElementsIsAnErrorNamingBoth) {
  Model model;
  Mesh mesh = squareMesh(model, 0.5);
  const std::size_t triangles = mesh.elementCount(2);
  try {
    partitionMesh(model, mesh, settings(1000));
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("1000"), std::string::npos) << message;
    EXPECT_NE(message.find(std::to_string(triangles)), std::string::npos) << message;
  }
  EXPECT_EQ(mesh.partitions(), nullptr);
}

TEST(Partition, SlicesFollowTheCentroids) {
  Model model;
  Mesh mesh = squareMesh(model, 0.05);
  partitionMeshBySlices(model, mesh, {4, 1, 1}, {});
  ASSERT_EQ(mesh.partitions()->count, 4);
  for (const PartitionEntity& piece : mesh.partitions()->entities)
    for (const ElementBlock& b : piece.blocks) {
      if (dimension(b.type) != 2) continue;
      const int p = piece.partitions.front();
      for (std::size_t i = 0; i < b.size(); ++i) {
        double x = 0;
        for (int k = 0; k < 3; ++k) x += mesh.node(b.element(i)[k]).x / 3;
        EXPECT_GE(x, (p - 1) * 0.25 - 0.05);
        EXPECT_LE(x, p * 0.25 + 0.05);
      }
    }
}

TEST(Partition, PhysicalGroupsPerPartitionSetAreNamedAfterTheirParts) {
  Model model;
  Mesh mesh = squareMesh(model, 0.1);
  model.addPhysicalGroup({2, 7, "plate", {1}});
  PartitionSettings s = settings(2);
  s.topology.createPhysicals = true;
  partitionMesh(model, mesh, s);
  std::set<std::string> names;
  for (const PhysicalGroup& g : mesh.partitions()->physicalGroups) {
    names.insert(g.name);
    EXPECT_GT(g.tag, 7);
  }
  EXPECT_TRUE(names.contains("_part{1}_physical{7}_dim{2}"));
  EXPECT_TRUE(names.contains("_part{2}_physical{7}_dim{2}"));
  EXPECT_TRUE(names.contains("_part{1,2}_physical{7}_dim{1}"));
  for (const PartitionEntity& piece : mesh.partitions()->entities)
    EXPECT_EQ(piece.physicals.size(), 1u);
}

TEST(Partition, WithoutTopologyOnlyPiecesOfModelEntitiesAreMade) {
  Model model;
  Mesh mesh = squareMesh(model, 0.05);
  PartitionSettings s = settings(3);
  s.topology.createTopology = false;
  partitionMesh(model, mesh, s);
  std::size_t placed = 0;
  for (const PartitionEntity& piece : mesh.partitions()->entities) {
    EXPECT_EQ(piece.parent.dim, piece.id.dim);
    placed += piece.nodes.size();
  }
  EXPECT_EQ(placed, mesh.nodeCount());
}

}  // namespace
}  // namespace geomesh
