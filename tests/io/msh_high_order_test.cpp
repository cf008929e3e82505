// Every element type of the table, high-order ones included, written and read back in MSH 4.1
// and 2.2, ASCII and binary: same types, same node order, same coordinates.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "io/msh_reader.h"
#include "io/msh_writer.h"
#include "mesh/high_order/reference_element.h"

namespace geomesh {
namespace {

// A fixed non-degenerate affine map, shifted per element so that no two elements overlap.
Vec3 placed(const std::array<double, 3>& xi, int shift) {
  return {1.0 + 2.0 * xi[0] + 0.3 * xi[1] + 0.1 * xi[2] + 5.0 * shift,
          -2.0 + 0.2 * xi[0] + 1.5 * xi[1] + 0.4 * xi[2],
          3.0 + 0.1 * xi[0] - 0.3 * xi[1] + 1.2 * xi[2]};
}

// One element of every type, each on its own entity of the type's dimension (tag: its row in
// kElementTypes plus 1), its nodes at an affine image of the reference nodes, all held by that
// entity.
void buildEveryType(Mesh& mesh) {
  int row = 0;
  for (const ElementTypeInfo& info : kElementTypes) {
    ++row;
    EntityMesh& em = mesh.entity({dimension(info.type), row});
    ElementBlock& block = em.block(info.type);
    for (const std::array<double, 3>& xi : referenceElement(info.type).xi) {
      const NodeIndex n = mesh.addNode(placed(xi, row));
      em.nodes.push_back(n);
      block.nodes.push_back(n);
    }
  }
}

// Each element's node coordinates in order, per entity and type, from `mesh`.
void expectSameElements(const Mesh& expected, const Mesh& actual, const std::string& what) {
  for (const auto& [id, em] : expected.entities()) {
    const EntityMesh* read = actual.find(id);
    ASSERT_NE(read, nullptr) << what << ": entity " << id.dim << " " << id.tag;
    for (const ElementBlock& block : em.blocks) {
      const ElementBlock* back = read->findBlock(block.type);
      ASSERT_NE(back, nullptr) << what << ": " << elementName(block.type);
      ASSERT_EQ(back->nodes.size(), block.nodes.size()) << what << ": " << elementName(block.type);
      for (std::size_t k = 0; k < block.nodes.size(); ++k) {
        const double d = distance(expected.node(block.nodes[k]), actual.node(back->nodes[k]));
        EXPECT_LT(d, 1e-13) << what << ": " << elementName(block.type) << " node " << k;
      }
      // Distinct nodes in the element stay distinct: the connectivity is the same.
      std::vector<NodeIndex> sorted = back->nodes;
      std::sort(sorted.begin(), sorted.end());
      EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end())
          << what << ": " << elementName(block.type);
    }
  }
  EXPECT_EQ(actual.elementCount(-1), expected.elementCount(-1)) << what;
  EXPECT_EQ(actual.nodeCount(), expected.nodeCount()) << what;
}

struct Variant {
  double version;
  bool binary;
};

class MshHighOrder : public ::testing::TestWithParam<Variant> {};

TEST_P(MshHighOrder, EveryElementTypeRoundTrips) {
  const Variant v = GetParam();
  const std::string what = std::to_string(v.version) + (v.binary ? " binary" : " ASCII");
  Model model;
  Mesh mesh;
  buildEveryType(mesh);
  std::ostringstream out;
  writeMsh(out, model, mesh, {true, v.binary, v.version});
  std::istringstream in(out.str());
  Model readModel;
  Mesh readMesh;
  readMsh(in, readModel, readMesh, "every-type.msh");
  expectSameElements(mesh, readMesh, what);
}

INSTANTIATE_TEST_SUITE_P(Versions, MshHighOrder,
                         ::testing::Values(Variant{4.1, false}, Variant{4.1, true},
                                           Variant{2.2, false}, Variant{2.2, true}),
                         [](const ::testing::TestParamInfo<Variant>& info) {
                           return std::string(info.param.version > 4 ? "Msh41" : "Msh22") +
                                  (info.param.binary ? "Binary" : "Ascii");
                         });

TEST(MshHighOrderText, WritesEveryTypeUnderItsMshNumber) {
  for (const double version : {4.1, 2.2}) {
    Model model;
    Mesh mesh;
    buildEveryType(mesh);
    std::ostringstream out;
    writeMsh(out, model, mesh, {true, false, version});
    const std::string text = out.str();
    std::istringstream lines(text.substr(text.find("$Elements")));
    std::string line;
    std::getline(lines, line);
    std::getline(lines, line);  // counts
    std::vector<int> numbers;
    while (std::getline(lines, line) && line != "$EndElements") {
      std::istringstream fields(line);
      int a = 0, b = 0, c = 0;
      fields >> a >> b >> c;
      if (version > 4) {
        numbers.push_back(c);  // block header: dim, tag, type, count
        std::getline(lines, line);
      } else {
        numbers.push_back(b);  // element: tag, type, ...
      }
    }
    std::vector<int> expected;
    for (const ElementTypeInfo& info : kElementTypes)
      expected.push_back(static_cast<int>(info.type));
    std::sort(numbers.begin(), numbers.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(numbers, expected) << version;
  }
}

// Files for tools outside the tests (bench/high_order_ordering.py): for every type, one element
// alone in a file of each version and encoding ("triangle10-41-binary.msh"), written in the
// directory GEOMESH_HIGH_ORDER_SAMPLES names.
TEST(MshHighOrderSamples, WritesSampleFilesWhenAsked) {
  const char* dir = std::getenv("GEOMESH_HIGH_ORDER_SAMPLES");
  if (!dir) GTEST_SKIP() << "GEOMESH_HIGH_ORDER_SAMPLES is not set";
  for (const ElementTypeInfo& info : kElementTypes) {
    Model model;
    Mesh mesh;
    EntityMesh& em = mesh.entity({dimension(info.type), 1});
    for (const std::array<double, 3>& xi : referenceElement(info.type).xi) {
      const NodeIndex n = mesh.addNode(placed(xi, 0));
      em.nodes.push_back(n);
      em.block(info.type).nodes.push_back(n);
    }
    for (const Variant v : {Variant{4.1, false}, Variant{4.1, true}, Variant{2.2, false},
                            Variant{2.2, true}}) {
      const std::string name = std::string(info.name) + (v.version > 4 ? "-41" : "-22") +
                               (v.binary ? "-binary" : "") + ".msh";
      writeMshFile(std::string(dir) + "/" + name, model, mesh, {true, v.binary, v.version});
    }
  }
}

}  // namespace
}  // namespace geomesh
