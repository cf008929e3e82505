// Reading CGNS through the cgns row of the format table (a path reader): files geomesh writes
// read back with their element types, node orders, nodes and boundary groups; files that are
// not CGNS, or missing, are errors that leave nothing half-read.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/discrete_mesh.h"
#include "io/mesh_scanner.h"
#include "tests/io/format_test_meshes.h"
#include "tests/io/solver_format_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using testing::countsByType;
using testing::elementsByType;
using T = ElementType;

const MeshFormat& cgns() {
  return *findFormatByName("cgns");
}

testing::ReadBack writeAndRead(const Model& model, const Mesh& mesh, const std::string& name,
                               bool saveAll = true) {
  const std::filesystem::path path = scratch::path(name);
  MeshWriteOptions options;
  options.saveAll = saveAll;
  writeMeshFile(path.string(), cgns(), model, mesh, options);
  testing::ReadBack back;
  readMeshFile(path.string(), cgns(), back.model, back.mesh);
  std::filesystem::remove(path);
  return back;
}

// Per (dimension, name) of the physical groups: how many elements their entities hold.
std::map<std::pair<int, std::string>, std::size_t> groupSizes(const testing::ReadBack& r) {
  std::map<std::pair<int, std::string>, std::size_t> sizes;
  for (const auto& [id, group] : r.model.physicalGroups())
    for (int tag : group.entities)
      if (const EntityMesh* em = r.mesh.find({group.dim, tag}))
        sizes[{group.dim, group.name}] += em->elementCount();
  return sizes;
}

std::size_t usedNodeCount(const Mesh& mesh) {
  std::vector<char> used(mesh.nodeCount(), 0);
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks)
      for (NodeIndex n : b.nodes) used[n] = 1;
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
}

void expectPositiveVolumes(const Mesh& mesh) {
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks) {
      if (dimension(b.type) != 3) continue;
      for (std::size_t e = 0; e < b.size(); ++e) {
        std::vector<Vec3> corners;
        for (NodeIndex n : b.element(e)) corners.push_back(mesh.node(n));
        EXPECT_GT(testing::cornerVolume6(family(b.type), corners), 0) << elementName(b.type);
      }
    }
}

TEST(CgnsReader, IsFoundByExtensionAndListedAmongTheFilesRead) {
  EXPECT_EQ(findReaderByExtension(".cgns"), &cgns());
  EXPECT_EQ(cgns().read, nullptr);
  EXPECT_NE(cgns().readFile, nullptr);
  EXPECT_TRUE(cgns().reads());
  EXPECT_NE(readExtensionList().find(".cgns"), std::string::npos);
}

TEST(CgnsReader, A3DMixedMeshReadsBackWithItsTypesNodesAndBoundaryGroups) {
  Model model;
  Mesh mesh;
  testing::buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  const testing::ReadBack back = writeAndRead(model, mesh, "read-3d.cgns");
  EXPECT_EQ(countsByType(back.mesh), countsByType(mesh));
  EXPECT_EQ(back.mesh.nodeCount(), usedNodeCount(mesh));
  EXPECT_EQ(elementsByType(back.mesh), elementsByType(mesh));
  expectPositiveVolumes(back.mesh);
  // The boundary group and the volume groups keep their names; the other elements are
  // grouped by section.
  using G = std::map<std::pair<int, std::string>, std::size_t>;
  EXPECT_EQ(groupSizes(back), (G{{{0, "Point5_NODE"}, 1},
                                 {{1, "Curve4_BAR_2"}, 2},
                                 {{2, "Surface6_TRI_3"}, 1},
                                 {{2, "wall"}, 3},
                                 {{3, "PhysicalVolume11"}, 3},
                                 {{3, "solid"}, 1}}));
}

// The cube's surface, its faces mixed triangles and quadrangles, and two of its edges in the
// curve group "edges".
void buildCubeSurfaceWithEdges(Model& model, Mesh& mesh) {
  for (int i = 0; i < 8; ++i) mesh.addNode(testing::cubeCorner(i));
  const auto faces = testing::cubeFaces();
  for (int k = 0; k < 6; ++k) {
    const std::vector<NodeIndex>& f = faces[k];
    ElementBlock& block = mesh.entity({2, k + 1}).block(k < 3 ? T::Triangle3 : T::Quad4);
    block.nodes = k < 3 ? std::vector<NodeIndex>{f[0], f[1], f[2], f[0], f[2], f[3]} : f;
  }
  mesh.entity({1, 7}).block(T::Line2).nodes = {0, 1};
  mesh.entity({1, 8}).block(T::Line2).nodes = {1, 3};
  addDiscreteEntities(model, mesh, {{1, 1, "edges", {7, 8}}, {2, 2, "skin", {1, 2, 3, 4, 5, 6}}});
}

TEST(CgnsReader, A2DMixedMeshReadsBackWithItsTypesNodesAndBoundaryGroups) {
  Model model;
  Mesh mesh;
  buildCubeSurfaceWithEdges(model, mesh);
  const testing::ReadBack back = writeAndRead(model, mesh, "read-2d.cgns", false);
  EXPECT_EQ(countsByType(back.mesh),
            (std::map<ElementType, std::size_t>{{T::Line2, 2}, {T::Triangle3, 6}, {T::Quad4, 3}}));
  EXPECT_EQ(back.mesh.nodeCount(), 8u);
  EXPECT_EQ(elementsByType(back.mesh), elementsByType(mesh));
  const auto sizes = groupSizes(back);
  EXPECT_EQ(sizes.at({1, "edges"}), 2u);
  std::size_t surfaceElements = 0;
  for (const auto& [key, size] : sizes)
    if (key.first == 2) surfaceElements += size;
  EXPECT_EQ(surfaceElements, 9u);
}

TEST(CgnsReader, SecondOrderElementsKeepTheirNodeOrders) {
  Model model;
  Mesh mesh;
  const std::vector<T> types = {T::Line3,   T::Triangle6, T::Quad8,     T::Quad9,
                                T::Tet10,   T::Pyramid13, T::Pyramid14, T::Prism15,
                                T::Prism18, T::Hex20,     T::Hex27};
  for (T type : types)
    testing::addReferenceElement(mesh, {dimension(type), 1}, type,
                                 {5.0 * static_cast<int>(type), 0, 0});
  const testing::ReadBack back = writeAndRead(model, mesh, "read-order2.cgns");
  EXPECT_EQ(countsByType(back.mesh), countsByType(mesh));
  EXPECT_EQ(elementsByType(back.mesh), elementsByType(mesh));
  expectPositiveVolumes(back.mesh);
}

TEST(CgnsReader, SeveralReadsReplaceTheModel) {
  Model model;
  Mesh mesh;
  testing::buildHexCube(model, mesh);
  testing::ReadBack back = writeAndRead(model, mesh, "read-twice.cgns");
  const std::filesystem::path path = scratch::path("read-twice-2.cgns");
  writeMeshFile(path.string(), cgns(), model, mesh, {});
  readMeshFile(path.string(), cgns(), back.model, back.mesh);
  std::filesystem::remove(path);
  EXPECT_EQ(back.mesh.nodeCount(), 8u);
  EXPECT_EQ(back.mesh.elementCount(3), 1u);
}

// The error of reading `path`, checking that nothing is left half-read.
std::string readError(const std::string& path) {
  Model model;
  Mesh mesh;
  mesh.addNode({1, 2, 3});
  try {
    readMeshFile(path, cgns(), model, mesh);
  } catch (const std::runtime_error& e) {
    if (mesh.nodeCount() != 0 && std::string(e.what()).rfind("cannot open", 0) != 0)
      return "half-read result";
    return e.what();
  }
  return "no error";
}

TEST(CgnsReader, AFileThatIsNotCgnsIsAnErrorNamingIt) {
  const std::filesystem::path path = scratch::path("not.cgns");
  std::ofstream(path) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  Model model;
  Mesh mesh;
  mesh.addNode({1, 2, 3});
  EXPECT_THROW(readMeshFile(path.string(), cgns(), model, mesh), MeshReadError);
  EXPECT_EQ(mesh.nodeCount(), 0u);
  const std::string error = readError(path.string());
  EXPECT_EQ(error.rfind(path.string() + ": cannot read it as CGNS: ", 0), 0u) << error;
  std::filesystem::remove(path);
}

TEST(CgnsReader, AMissingFileIsAnError) {
  const std::string path = scratch::path("missing.cgns").string();
  EXPECT_EQ(readError(path), "cannot open '" + path + "'");
}

}  // namespace
}  // namespace geomesh
