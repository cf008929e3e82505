// The legacy VTK reader: what the writer saves (ASCII and binary) reads back to the same
// elements, entities and node orders; files of other writers (no cell data, gmsh:physical
// fields, VTK 5 offsets, POLYDATA, pixels and voxels); malformed files are errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "mesh/high_order/reference_element.h"
#include "tests/io/format_test_meshes.h"

namespace geomesh {
namespace {

using namespace testing;

// The cube's mixed surface, its hexahedron on volume 1, a line on curve 4 and a point on
// point 2.
void buildMixed(Model& model, Mesh& mesh) {
  for (int i = 0; i < 8; ++i) mesh.addNode(cubeCorner(i));
  const auto faces = cubeFaces();
  for (int k = 0; k < 6; ++k) {
    const auto& f = faces[k];
    if (k < 3)
      mesh.entity({2, k + 1}).block(ElementType::Triangle3).nodes = {f[0], f[1], f[2],
                                                                      f[0], f[2], f[3]};
    else
      mesh.entity({2, k + 1}).block(ElementType::Quad4).nodes = f;
  }
  mesh.entity({3, 1}).block(ElementType::Hex8).nodes = {0, 1, 3, 2, 4, 5, 7, 6};
  mesh.entity({1, 4}).block(ElementType::Line2).nodes = {0, 1};
  mesh.entity({0, 2}).block(ElementType::Point1).nodes = {7};
  addDiscreteEntities(model, mesh);
}

// The node coordinates, sorted: the file orders nodes by entity.
std::vector<std::array<double, 3>> nodesOf(const Mesh& mesh) {
  std::vector<std::array<double, 3>> out;
  for (std::size_t i = 0; i < mesh.nodeCount(); ++i) {
    const Vec3 p = mesh.node(NodeIndex(i));
    out.push_back({p.x, p.y, p.z});
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(VtkReader, AsciiAndBinaryReadBackToTheWrittenEntities) {
  Model model;
  Mesh mesh;
  buildMixed(model, mesh);
  for (bool binary : {false, true}) {
    const ReadBack r = readAs("vtk", writeAs("vtk", model, mesh, binary));
    EXPECT_EQ(countsByEntity(r.mesh), countsByEntity(mesh)) << binary;
    EXPECT_EQ(nodesOf(r.mesh), nodesOf(mesh)) << binary;
    EXPECT_EQ(r.model.entities(-1).size(), 9u) << binary;
    EXPECT_TRUE(r.model.physicalGroups().empty());
    // The hexahedron's nodes come back in MSH order.
    const ElementBlock* hex = r.mesh.find({3, 1})->findBlock(ElementType::Hex8);
    ASSERT_NE(hex, nullptr);
    for (int k = 0; k < 8; ++k)
      EXPECT_EQ(r.mesh.node(hex->nodes[k]), mesh.node(mesh.find({3, 1})->blocks[0].nodes[k]));
  }
}

// One element of `type`, its nodes at a distorted image of the reference nodes.
void buildOneElement(ElementType type, Model& model, Mesh& mesh) {
  ElementBlock& block = mesh.entity({dimension(type), 1}).block(type);
  for (const std::array<double, 3>& xi : referenceElement(type).xi)
    block.nodes.push_back(mesh.addNode({1 + 2 * xi[0] + 0.3 * xi[1], xi[1] - 0.2 * xi[2],
                                        3 * xi[2] + 0.1 * xi[0]}));
  addDiscreteEntities(model, mesh);
}

TEST(VtkReader, EveryWrittenTypeReadsBackWithItsNodesInPlace) {
  for (const ElementTypeInfo& info : kElementTypes) {
    if (info.order > 2 || info.type == ElementType::Pyramid14) continue;
    Model model;
    Mesh mesh;
    buildOneElement(info.type, model, mesh);
    for (bool binary : {false, true}) {
      const ReadBack r = readAs("vtk", writeAs("vtk", model, mesh, binary));
      const ElementBlock* block = r.mesh.find({dimension(info.type), 1})->findBlock(info.type);
      ASSERT_NE(block, nullptr) << info.name;
      ASSERT_EQ(block->size(), 1u);
      for (int k = 0; k < info.nodes; ++k)
        EXPECT_EQ(r.mesh.node(block->nodes[k]), mesh.node(NodeIndex(k))) << info.name << k;
    }
  }
}

const char* kSquareHeader =
    "# vtk DataFile Version 3.0\nsquare\nASCII\nDATASET UNSTRUCTURED_GRID\n"
    "POINTS 4 float\n0 0 0 1 0 0\n1 1 0 0 1 0\n";

TEST(VtkReader, WithoutCellDataEachDimensionIsOneEntity) {
  const ReadBack r = readAs("vtk", std::string(kSquareHeader) +
                                       "CELLS 4 13\n3 0 1 2\n3 0 2 3\n2 0 1\n1 3\n"
                                       "CELL_TYPES 4\n5\n5\n3\n1\n");
  EXPECT_EQ(r.mesh.find({2, 1})->elementCount(), 2u);
  EXPECT_EQ(r.mesh.find({1, 1})->elementCount(), 1u);
  EXPECT_EQ(r.mesh.find({0, 1})->elementCount(), 1u);
  EXPECT_EQ(r.model.entities(-1).size(), 3u);
  EXPECT_EQ(r.model.point(1)->xyz, (Vec3{0, 1, 0}));
}

TEST(VtkReader, GmshFieldArraysGiveEntitiesAndPhysicalGroups) {
  const ReadBack r = readAs(
      "vtk", std::string(kSquareHeader) +
                 "CELLS 3 11\n3 0 1 2\n3 0 2 3\n2 0 1\nCELL_TYPES 3\n5 5 3\n"
                 "POINT_DATA 4\nSCALARS temperature double\nLOOKUP_TABLE default\n1 2 3 4\n"
                 "CELL_DATA 3\nFIELD FieldData 3\nquality 1 3 double\n0.5 0.7 1\n"
                 "gmsh:physical 1 3 int\n7 7 0\ngmsh:geometrical 1 3 int\n4 5 2\n");
  const auto counts = countsByEntity(r.mesh);
  EXPECT_EQ((counts.at({{2, 4}, ElementType::Triangle3})), 1u);
  EXPECT_EQ((counts.at({{2, 5}, ElementType::Triangle3})), 1u);
  EXPECT_EQ((counts.at({{1, 2}, ElementType::Line2})), 1u);
  ASSERT_EQ(r.model.physicalGroups().size(), 1u);
  const PhysicalGroup& group = r.model.physicalGroups().begin()->second;
  EXPECT_EQ(group.dim, 2);
  EXPECT_EQ(group.tag, 7);
  EXPECT_EQ(group.entities, (std::vector<int>{4, 5}));
}

TEST(VtkReader, ReadsPastTheDataArraysItDoesNotUse) {
  const ReadBack r = readAs(
      "vtk", std::string(kSquareHeader) +
                 "CELLS 2 8\n3 0 1 2\n3 0 2 3\nCELL_TYPES 2\n5 5\n"
                 "POINT_DATA 4\nNORMALS n float\n0 0 1 0 0 1 0 0 1 0 0 1\n"
                 "VECTORS v double\n1 2 3 4 5 6 7 8 9 10 11 12\n"
                 "COLOR_SCALARS c 2\n0 1 0.5 0.5 1 1 0 0\n"
                 "TEXTURE_COORDINATES t 2 float\n0 0 1 0 1 1 0 1\n"
                 "LOOKUP_TABLE lut 2\n0 0 0 1 1 1 1 1\n"
                 "CELL_DATA 2\nTENSORS s float\n1 0 0 0 1 0 0 0 1 1 0 0 0 1 0 0 0 1\n"
                 "SCALARS CellEntityIds int 1\n6 9\n"
                 "SCALARS pair float 2\nLOOKUP_TABLE default\n1 2 3 4\n");
  const auto counts = countsByEntity(r.mesh);
  EXPECT_EQ((counts.at({{2, 6}, ElementType::Triangle3})), 1u);
  EXPECT_EQ((counts.at({{2, 9}, ElementType::Triangle3})), 1u);
}

TEST(VtkReader, ReadsPastBinaryDataArrays) {
  Model model;
  Mesh mesh;
  buildMixed(model, mesh);
  std::string bytes = writeAs("vtk", model, mesh, true);
  bytes += "POINT_DATA 8\nVECTORS v float\n" + std::string(8 * 12, '\x3f') + "\n";
  bytes += "COLOR_SCALARS c 3\n" + std::string(8 * 3, '\x01') + "\n";
  const ReadBack r = readAs("vtk", bytes);
  EXPECT_EQ(countsByEntity(r.mesh), countsByEntity(mesh));
}

TEST(VtkReader, ReadsVtk5OffsetsAndConnectivity) {
  const ReadBack r = readAs(
      "vtk", "# vtk DataFile Version 5.1\nv5\nASCII\nDATASET UNSTRUCTURED_GRID\n"
             "POINTS 5 double\n0 0 0 1 0 0 1 1 0 0 1 0 0 0 1\nMETADATA\nINFORMATION 0\n\n"
             "CELLS 3 8\nOFFSETS vtktypeint64\n0 4 8\nCONNECTIVITY vtktypeint64\n"
             "0 1 2 3 0 1 3 4\nCELL_TYPES 2\n9\n10\n"
             "CELL_DATA 2\nSCALARS CellEntityIds int 1\nLOOKUP_TABLE default\n3 8\n");
  const auto counts = countsByEntity(r.mesh);
  EXPECT_EQ((counts.at({{2, 3}, ElementType::Quad4})), 1u);
  EXPECT_EQ((counts.at({{3, 8}, ElementType::Tet4})), 1u);
  EXPECT_EQ(counts.size(), 2u);
}

TEST(VtkReader, ReadsPolydata) {
  const ReadBack r = readAs(
      "vtk", "# vtk DataFile Version 2.0\npoly\nASCII\nDATASET POLYDATA\n"
             "POINTS 5 float\n0 0 0 1 0 0 1 1 0 0 1 0 2 0 0\n"
             "VERTICES 1 3\n2 0 4\nLINES 1 4\n3 0 1 4\n"
             "POLYGONS 2 9\n3 0 1 2\n4 0 1 2 3\nTRIANGLE_STRIPS 1 5\n4 0 1 3 2\n"
             "CELL_DATA 5\nSCALARS part int\nLOOKUP_TABLE default\n1 2 3 3 4\n");
  const auto counts = countsByEntity(r.mesh);
  EXPECT_EQ((counts.at({{0, 1}, ElementType::Point1})), 2u);
  EXPECT_EQ((counts.at({{1, 2}, ElementType::Line2})), 2u);
  EXPECT_EQ((counts.at({{2, 3}, ElementType::Triangle3})), 1u);
  EXPECT_EQ((counts.at({{2, 3}, ElementType::Quad4})), 1u);
  EXPECT_EQ((counts.at({{2, 4}, ElementType::Triangle3})), 2u);
  // The strip's second triangle turns the same way as the first: 3 1 2 after 0 1 3.
  const ElementBlock* strip = r.mesh.find({2, 4})->findBlock(ElementType::Triangle3);
  const auto at = [&](int i) { return r.mesh.node(strip->nodes[i]); };
  EXPECT_EQ(at(3), (Vec3{0, 1, 0}));
  EXPECT_EQ(at(4), (Vec3{1, 0, 0}));
  EXPECT_EQ(at(5), (Vec3{1, 1, 0}));
}

TEST(VtkReader, PixelsAndVoxelsBecomeQuadranglesAndHexahedra) {
  std::string text =
      "# vtk DataFile Version 2.0\nv\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n";
  for (int i = 0; i < 8; ++i) {
    const Vec3 p = cubeCorner(i);
    text += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  }
  text += "CELLS 2 14\n4 0 1 2 3\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 2\n8\n11\n";
  const ReadBack r = readAs("vtk", text);
  const ElementBlock* quad = r.mesh.find({2, 1})->findBlock(ElementType::Quad4);
  const ElementBlock* hex = r.mesh.find({3, 1})->findBlock(ElementType::Hex8);
  ASSERT_TRUE(quad && hex);
  const int quadCorners[] = {0, 1, 3, 2};
  for (int k = 0; k < 4; ++k) EXPECT_EQ(r.mesh.node(quad->nodes[k]), cubeCorner(quadCorners[k]));
  const int hexCorners[] = {0, 1, 3, 2, 4, 5, 7, 6};
  for (int k = 0; k < 8; ++k) EXPECT_EQ(r.mesh.node(hex->nodes[k]), cubeCorner(hexCorners[k]));
}

TEST(VtkReader, MalformedFilesAreErrorsNamingTheFileAndLine) {
  const std::string square = kSquareHeader;
  EXPECT_EQ(readErrorOf("vtk", "hello\n", "x.vtk"),
            "x.vtk:1: not a legacy VTK file: no '# vtk DataFile Version' line");
  EXPECT_EQ(readErrorOf("vtk", "# vtk DataFile Version 2.0\nt\nASCII\nDATASET STRUCTURED_POINTS\n",
                        "x.vtk"),
            "x.vtk:4: unsupported dataset STRUCTURED_POINTS (UNSTRUCTURED_GRID and POLYDATA "
            "are read)");
  EXPECT_EQ(readErrorOf("vtk", square + "CELLS 1 4\n3 0 1 9\nCELL_TYPES 1\n5\n", "x.vtk"),
            "x.vtk:8: a cell uses point 9, but the file has 4 points");
  EXPECT_EQ(readErrorOf("vtk", square + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n42\n", "x.vtk"),
            "x.vtk:8: cell 0: unsupported VTK cell type 42 with 3 nodes");
  EXPECT_EQ(readErrorOf("vtk", square + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n9\n", "x.vtk"),
            "x.vtk:8: cell 0: unsupported VTK cell type 9 with 3 nodes");
  EXPECT_EQ(readErrorOf("vtk", square + "CELLS 1 4\n4 0 1 2\n", "x.vtk"),
            "x.vtk:8: cell 0 runs past the end of its list");
  EXPECT_EQ(readErrorOf("vtk", square + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 2\n5\n5\n", "x.vtk"),
            "x.vtk:10: the file has 1 cells and 2 cell types");
  EXPECT_EQ(readErrorOf("vtk", square + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n"
                                        "CELL_DATA 1\nSCALARS CellEntityIds int\n-2\n",
                        "x.vtk"),
            "x.vtk:14: cell 0 has tag -2.000000 in 'CellEntityIds': tags are integers from 0");
  EXPECT_EQ(readErrorOf("vtk", square + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\nWHATEVER 3\n",
                        "x.vtk"),
            "x.vtk:12: unexpected keyword 'WHATEVER'");
  EXPECT_EQ(readErrorOf("vtk", square + "CELLS 1000000 4000000\n3 0 1 2\n", "x.vtk"),
            "x.vtk:8: a cell count 1000000 exceeds the size of the file");
}

TEST(VtkReader, APolygonOfFiveNodesIsAnError) {
  const std::string text =
      "# vtk DataFile Version 2.0\np\nASCII\nDATASET POLYDATA\nPOINTS 5 float\n"
      "0 0 0 1 0 0 1 1 0 0 1 0 2 0 0\nPOLYGONS 1 6\n5 0 1 2 3 4\n";
  EXPECT_EQ(readErrorOf("vtk", text, "p.vtk"),
            "p.vtk:7: cell 0: a polygon of 5 nodes (triangles and quadrangles are read)");
}

TEST(VtkReader, ATruncatedBinaryFileIsAnError) {
  Model model;
  Mesh mesh;
  buildMixed(model, mesh);
  const std::string bytes = writeAs("vtk", model, mesh, true);
  for (std::size_t cut : {bytes.find("CELLS") - 30, bytes.find("CELL_TYPES") + 20,
                          bytes.size() - 9}) {
    const std::string error = readErrorOf("vtk", bytes.substr(0, cut), "b.vtk");
    EXPECT_EQ(error.rfind("b.vtk:", 0), 0u) << error;
    EXPECT_NE(error.find("exceed"), std::string::npos) << cut << ": " << error;
  }
}

TEST(VtkReader, AWrittenFileIsReadThroughTheTable) {
  EXPECT_EQ(findReaderByExtension(".vtk"), findFormatByName("vtk"));
  EXPECT_NE(readExtensionList().find(".vtk"), std::string::npos);
}

TEST(VtkReader, DamagedFilesAreErrorsNeverCrashes) {
  Model model;
  Mesh mesh;
  buildMixed(model, mesh);
  expectDamageIsReported("vtk", writeAs("vtk", model, mesh));
  expectDamageIsReported("vtk", writeAs("vtk", model, mesh, true));
}

}  // namespace
}  // namespace geomesh
