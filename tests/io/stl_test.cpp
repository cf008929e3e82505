// STL through its row of the format table: solids per group or surface, facets and their
// normals, the binary layout, the refusal of meshes without surface elements, and the reader
// (ASCII and binary, merged vertices, errors on malformed files).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/io/format_test_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using namespace testing;

struct Facet {
  Vec3 normal;
  std::vector<Vec3> vertices;
};

struct Solid {
  std::string name;
  std::vector<Facet> facets;
};

Vec3 readVec(std::istream& in) {
  Vec3 p;
  in >> p.x >> p.y >> p.z;
  return p;
}

std::vector<Solid> parseAscii(const std::string& text) {
  std::vector<Solid> solids;
  std::istringstream in(text);
  std::string word;
  while (in >> word) {
    if (word == "solid") {
      solids.push_back({});
      std::getline(in >> std::ws, solids.back().name);
    } else if (word == "normal") {
      solids.back().facets.push_back({readVec(in), {}});
    } else if (word == "vertex") {
      solids.back().facets.back().vertices.push_back(readVec(in));
    }
  }
  return solids;
}

std::vector<Facet> parseBinary(const std::string& bytes) {
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);
  std::vector<Facet> facets;
  for (std::uint32_t i = 0; i < n; ++i) {
    float values[12];
    std::memcpy(values, bytes.data() + 84 + 50 * i, sizeof values);
    Facet f{{values[0], values[1], values[2]}, {}};
    for (int v = 0; v < 3; ++v)
      f.vertices.push_back({values[3 + 3 * v], values[4 + 3 * v], values[5 + 3 * v]});
    facets.push_back(f);
  }
  return facets;
}

Vec3 centroid(const Facet& f) {
  return (f.vertices[0] + f.vertices[1] + f.vertices[2]) / 3.0;
}

// Each facet's normal is the unit normal of its vertices by the right-hand rule, and points
// away from the cube's centre.
void expectOutwardNormals(const std::vector<Facet>& facets, double tolerance) {
  const Vec3 centre{0.5, 0.5, 0.5};
  for (const Facet& f : facets) {
    ASSERT_EQ(f.vertices.size(), 3u);
    const Vec3 n = normalized(cross(f.vertices[1] - f.vertices[0], f.vertices[2] - f.vertices[0]));
    EXPECT_LT(distance(n, f.normal), tolerance);
    EXPECT_GT(dot(f.normal, centroid(f) - centre), 0.49);
  }
}

TEST(Stl, IsFoundByNameExtensionAndCode) {
  const MeshFormat* stl = findFormatByName("stl");
  ASSERT_NE(stl, nullptr);
  EXPECT_EQ(findFormatByExtension(".stl", 4.1), stl);
  EXPECT_EQ(findFormatByCode(27, 4.1), stl);
  EXPECT_EQ(findReaderByExtension(".stl"), stl);
  EXPECT_EQ(stl->maxOrder, 1);
  EXPECT_NE(formatCodeList().find("27 (stl)"), std::string::npos) << formatCodeList();
}

TEST(Stl, OneSolidPerSurfaceWithoutGroupsQuadranglesSplitInTwo) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const std::vector<Solid> solids = parseAscii(writeAs("stl", model, mesh));
  ASSERT_EQ(solids.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(solids[k].name, "surface" + std::to_string(k + 1));
    EXPECT_EQ(solids[k].facets.size(), 2u);
  }
  // The quadrangle 1 3 7 5 of the +x face: triangles 1 3 7 and 1 7 5.
  const Facet& second = solids[5].facets[1];
  EXPECT_EQ(second.vertices[0], cubeCorner(1));
  EXPECT_EQ(second.vertices[1], cubeCorner(7));
  EXPECT_EQ(second.vertices[2], cubeCorner(5));
}

TEST(Stl, AsciiNormalsPointOutwards) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  std::vector<Facet> facets;
  for (const Solid& s : parseAscii(writeAs("stl", model, mesh)))
    facets.insert(facets.end(), s.facets.begin(), s.facets.end());
  ASSERT_EQ(facets.size(), 12u);
  expectOutwardNormals(facets, 1e-12);
}

TEST(Stl, OneSolidPerPhysicalSurfaceNamedByItsGroup) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  model.addPhysicalGroup({2, 3, "side walls", {3, 4, 5, 6}});
  model.addPhysicalGroup({2, 8, "", {1}});
  std::string text = writeAs("stl", model, mesh);
  std::vector<Solid> solids = parseAscii(text);
  ASSERT_EQ(solids.size(), 2u) << text;
  EXPECT_EQ(solids[0].name, "side walls");
  EXPECT_EQ(solids[0].facets.size(), 8u);
  EXPECT_EQ(solids[1].name, "PhysicalSurface8");
  EXPECT_EQ(solids[1].facets.size(), 2u);
  EXPECT_NE(text.find("endsolid side walls\n"), std::string::npos);
  // Mesh.SaveAll: every surface, one solid each.
  EXPECT_EQ(parseAscii(writeAs("stl", model, mesh, false, true)).size(), 6u);
}

TEST(Stl, BinaryLayoutHoldsOneSolidWithOutwardNormals) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const std::string bytes = writeAs("stl", model, mesh, true);
  ASSERT_EQ(bytes.size(), 84u + 50u * 12u);
  EXPECT_NE(bytes.substr(0, 5), "solid");
  const std::vector<Facet> facets = parseBinary(bytes);
  ASSERT_EQ(facets.size(), 12u);
  expectOutwardNormals(facets, 1e-6);
  for (std::size_t i = 0; i < 12; ++i) {
    std::uint16_t attributes = 1;
    std::memcpy(&attributes, bytes.data() + 84 + 50 * i + 48, 2);
    EXPECT_EQ(attributes, 0);
  }
}

TEST(Stl, PointsAndLinesAreLeftOut) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  mesh.entity({1, 1}).block(ElementType::Line2).nodes = {0, 1};
  mesh.entity({0, 1}).block(ElementType::Point1).nodes = {0};
  model.addCurve({1, 0, 0, nullptr});
  model.addPoint({1, {0, 0, 0}, 0});
  const std::vector<Solid> solids = parseAscii(writeAs("stl", model, mesh));
  EXPECT_EQ(solids.size(), 6u);
}

TEST(Stl, AVolumeMeshIsRefusedAndNoFileIsLeft) {
  expectVolumeMeshRefused("stl",
                          ": the mesh to save has 1 hexahedron elements and no surface element");
}

TEST(Stl, SurfaceElementsAboveOrderOneAreRefused) {
  Model model;
  Mesh mesh;
  for (int i = 0; i < 6; ++i) mesh.addNode({double(i), 0, 0});
  mesh.entity({2, 1}).block(ElementType::Triangle6).nodes = {0, 1, 2, 3, 4, 5};
  addDiscreteEntities(model, mesh);
  std::ostringstream out;
  try {
    findFormatByName("stl")->write(out, model, mesh, {});
    FAIL() << "written";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("triangle6"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("order 2"), std::string::npos) << e.what();
  }
  EXPECT_EQ(out.str(), "");
}

TEST(Stl, ReadingMakesASurfacePerSolidAndMergesEqualVertices) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const ReadBack r = readAs("stl", writeAs("stl", model, mesh));
  EXPECT_EQ(r.mesh.nodeCount(), 8u);
  const auto counts = countsByEntity(r.mesh);
  ASSERT_EQ(counts.size(), 6u);
  for (int k = 1; k <= 6; ++k) {
    EXPECT_EQ((counts.at({{2, k}, ElementType::Triangle3})), 2u) << k;
    EXPECT_NE(r.model.surface(k), nullptr);
  }
}

TEST(Stl, BinaryAndAsciiReadBackAlike) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const ReadBack ascii = readAs("stl", writeAs("stl", model, mesh));
  const ReadBack binary = readAs("stl", writeAs("stl", model, mesh, true));
  EXPECT_EQ(binary.mesh.nodeCount(), 8u);
  EXPECT_EQ(countsByType(binary.mesh), countsByType(ascii.mesh));
  EXPECT_EQ(countsByType(binary.mesh).at(ElementType::Triangle3), 12u);
  // Same triangles over the same points (the binary file has one solid).
  const auto triangles = [](const ReadBack& r) {
    std::vector<std::vector<double>> all;
    for (const auto& [id, em] : r.mesh.entities())
      for (const ElementBlock& b : em.blocks)
        for (std::size_t i = 0; i < b.size(); ++i) {
          std::vector<double> t;
          for (NodeIndex n : b.element(i))
            for (double c : {r.mesh.node(n).x, r.mesh.node(n).y, r.mesh.node(n).z}) t.push_back(c);
          all.push_back(t);
        }
    std::sort(all.begin(), all.end());
    return all;
  };
  EXPECT_EQ(triangles(binary), triangles(ascii));
}

TEST(Stl, OnlyExactlyEqualVerticesAreMerged) {
  const std::string text =
      "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid a\n"
      "solid b\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\n"
      "vertex 0 1.0000000000000002 0\nendloop\nendfacet\nendsolid\n";
  const ReadBack r = readAs("stl", text);
  EXPECT_EQ(r.mesh.nodeCount(), 5u);  // (1,0,0) is shared, (0,1,0) is not
  EXPECT_EQ(r.mesh.elementCount(2), 2u);
  EXPECT_EQ(r.mesh.find({2, 2})->elementCount(), 1u);
}

TEST(Stl, KeywordsMayBeUpperCase) {
  const ReadBack r = readAs("stl",
                            "SOLID PART\nFACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 0\n"
                            "VERTEX 1 0 0\nVERTEX 0 1 0\nENDLOOP\nENDFACET\nENDSOLID PART\n");
  EXPECT_EQ(r.mesh.elementCount(2), 1u);
}

TEST(Stl, ABinaryFileWhoseHeaderSaysSolidIsReadAsBinary) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  std::string bytes = writeAs("stl", model, mesh, true);
  bytes.replace(0, 10, "solid cube");
  const ReadBack r = readAs("stl", bytes);
  EXPECT_EQ(r.mesh.elementCount(2), 12u);
}

TEST(Stl, MalformedFilesAreErrorsNamingTheFileAndLine) {
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n";
  EXPECT_EQ(readErrorOf("stl", "solid x\n" + facet + "endloop\nendfacet\nendsolid\n", "s.stl"),
            "s.stl:6: expected 'vertex', found 'endloop': a facet has 3 vertices");
  EXPECT_EQ(readErrorOf("stl", "solid x\n" + facet + "vertex 0 1 0\nvertex 1 1 0\nendloop\n",
                        "s.stl"),
            "s.stl:7: a facet with more than 3 vertices");
  EXPECT_EQ(readErrorOf("stl", "solid x\n" + facet + "vertex 0 one 0\n", "s.stl"),
            "s.stl:6: expected a number, found 'one'");
  EXPECT_EQ(readErrorOf("stl", "solid x\n" + facet, "s.stl"),
            "s.stl:6: unexpected end of file");
  EXPECT_EQ(readErrorOf("stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 inf\n",
                        "s.stl"),
            "s.stl:4: non-finite number 'inf'");
  EXPECT_EQ(readErrorOf("stl", "", "e.stl"),
            "e.stl:1: not an STL file: no 'solid' at the start, and 0 bytes are too few for a "
            "binary one");
}

TEST(Stl, ATruncatedBinaryFileIsAnError) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  const std::string bytes = writeAs("stl", model, mesh, true);
  const std::string error = readErrorOf("stl", bytes.substr(0, bytes.size() - 7), "t.stl");
  EXPECT_EQ(error,
            "t.stl: binary STL truncated at byte 677 (facet 12 of 12): its header gives 12 "
            "facets, which take 684 bytes");
  // Cut at a facet's start: the data ran out where that facet should begin.
  EXPECT_EQ(readErrorOf("stl", bytes.substr(0, 84 + 50 * 5), "t.stl").substr(0, 60),
            "t.stl: binary STL truncated at byte 334 (facet 6 of 12): its");
}

TEST(Stl, AFileTooShortForItsCountWithoutBinaryDataIsNotCalledTruncated) {
  const std::string text(120, 'x');  // no 'solid', no NUL byte: not a binary file cut short
  const std::string error = readErrorOf("stl", text, "x.stl");
  EXPECT_NE(error.find("x.stl:1: not an ASCII STL file"), std::string::npos) << error;
}

TEST(Stl, ATruncatedBinaryFileWhoseHeaderSaysSolidIsAnError) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  std::string bytes = writeAs("stl", model, mesh, true);
  bytes.replace(0, 10, "solid cube");
  const std::string error = readErrorOf("stl", bytes.substr(0, 300), "t.stl");
  EXPECT_EQ(error,
            "t.stl: binary STL truncated at byte 300 (facet 5 of 12): its header gives 12 "
            "facets, which take 684 bytes");
}

TEST(Stl, ANonFiniteBinaryCoordinateIsAnError) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  mesh.setNode(7, {1, 1, std::numeric_limits<double>::infinity()});
  const std::string error = readErrorOf("stl", writeAs("stl", model, mesh, true), "n.stl");
  EXPECT_NE(error.find("n.stl: binary facet"), std::string::npos) << error;
  EXPECT_NE(error.find("non-finite"), std::string::npos) << error;
}

TEST(Stl, AWrittenFileIsMergedThroughTheTable) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const std::filesystem::path path = scratch::path("cube.stl");
  writeMeshFile(path.string(), *findFormatByName("stl"), model, mesh, {});
  Model readModel;
  Mesh readMesh;
  readMeshFile(path.string(), *findReaderByExtension(".stl"), readModel, readMesh);
  EXPECT_EQ(readMesh.elementCount(2), 12u);
  EXPECT_EQ(readModel.entities(2).size(), 6u);
  std::filesystem::remove(path);
}

TEST(Stl, DamagedFilesAreErrorsNeverCrashes) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  expectDamageIsReported("stl", writeAs("stl", model, mesh));
  expectDamageIsReported("stl", writeAs("stl", model, mesh, true));
}

}  // namespace
}  // namespace geomesh
