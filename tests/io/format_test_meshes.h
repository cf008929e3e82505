// Small meshes and helpers for the tests of the VTK, VTU, STL, PLY, OFF and OBJ formats: writing
// and reading through a row of the format table, counting elements per type.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/mesh_scanner.h"
#include "tests/scratch.h"

namespace geomesh::testing {

// The unit cube's corners, corner i at (i & 1, i >> 1 & 1, i >> 2 & 1).
inline Vec3 cubeCorner(int i) { return {double(i & 1), double(i >> 1 & 1), double(i >> 2 & 1)}; }

// The index of the cube corner at `p`, -1 if none.
inline int cornerAt(Vec3 p) {
  for (int i = 0; i < 8; ++i)
    if (cubeCorner(i) == p) return i;
  return -1;
}

// The cube's faces, each as a quadrangle whose corners turn counterclockwise seen from outside:
// -z, +z, -y, +y, -x, +x.
inline std::vector<std::vector<NodeIndex>> cubeFaces() {
  return {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
}

// The cube's surface, face k on surface k + 1, oriented outwards. With `mixed`, faces 1 to 3
// are split into two triangles each along their 0-2 diagonal and the others stay quadrangles.
inline void buildCubeSurface(Model& model, Mesh& mesh, bool mixed = false) {
  for (int i = 0; i < 8; ++i) mesh.addNode(cubeCorner(i));
  const auto faces = cubeFaces();
  for (int k = 0; k < 6; ++k) {
    const std::vector<NodeIndex>& f = faces[k];
    EntityMesh& em = mesh.entity({2, k + 1});
    if (mixed && k < 3)
      em.block(ElementType::Triangle3).nodes = {f[0], f[1], f[2], f[0], f[2], f[3]};
    else
      em.block(ElementType::Quad4).nodes = f;
  }
  addDiscreteEntities(model, mesh);
}

// The cube as one hexahedron on volume 1, and nothing else.
inline void buildHexCube(Model& model, Mesh& mesh) {
  for (int i = 0; i < 8; ++i) mesh.addNode(cubeCorner(i));
  mesh.entity({3, 1}).block(ElementType::Hex8).nodes = {0, 1, 3, 2, 4, 5, 7, 6};
  addDiscreteEntities(model, mesh);
}
// Writing a mesh of one hexahedron to a surface-only `format` fails with a message naming the
// format (and holding `detail`), and leaves no file and no partial file behind.
inline void expectVolumeMeshRefused(const char* format, const std::string& detail) {
  Model model;
  Mesh mesh;
  buildHexCube(model, mesh);
  const std::filesystem::path path = scratch::path(std::string("volume.") + format);
  try {
    writeMeshFile(path.string(), *findFormatByName(format), model, mesh, {});
    FAIL() << "written";
  } catch (const std::runtime_error& e) {
    const std::string expected =
        std::string(format) + " files hold surface elements only" + detail;
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
}


inline std::string writeAs(const char* format, const Model& model, const Mesh& mesh,
                           bool binary = false, bool saveAll = false) {
  std::ostringstream out;
  MeshWriteOptions options;
  options.binary = binary;
  options.saveAll = saveAll;
  findFormatByName(format)->write(out, model, mesh, options);
  return out.str();
}

struct ReadBack {
  Model model;
  Mesh mesh;
};

inline ReadBack readAs(const char* format, const std::string& text,
                       const std::string& name = "test.file") {
  ReadBack r;
  std::istringstream in(text);
  findFormatByName(format)->read(in, r.model, r.mesh, name);
  return r;
}

// The reader's error message, or "no error"; checks that nothing is left half-read.
inline std::string readErrorOf(const char* format, const std::string& text,
                               const std::string& name = "bad.file") {
  Model model;
  Mesh mesh;
  mesh.addNode({1, 2, 3});
  std::istringstream in(text);
  try {
    findFormatByName(format)->read(in, model, mesh, name);
  } catch (const MeshReadError& e) {
    if (mesh.nodeCount() != 0 || !model.entities(-1).empty()) return "half-read result";
    return e.what();
  }
  return "no error";
}

// Reads every prefix of `bytes`, and copies of `bytes` with one byte changed at many places:
// each read must give a mesh or throw MeshReadError, never anything else.
inline void expectDamageIsReported(const char* format, const std::string& bytes) {
  const auto read = [&](const std::string& damaged, const std::string& what) {
    Model model;
    Mesh mesh;
    std::istringstream in(damaged);
    try {
      findFormatByName(format)->read(in, model, mesh, "damaged");
    } catch (const MeshReadError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << format << ", " << what << ": " << e.what();
    }
  };
  for (std::size_t n = 0; n < bytes.size(); ++n)
    read(bytes.substr(0, n), "prefix of " + std::to_string(n));
  std::mt19937 random(7);
  for (int i = 0; i < 3000; ++i) {
    std::string damaged = bytes;
    const std::size_t at = random() % bytes.size();
    damaged[at] = static_cast<char>(random() % 256);
    read(damaged, "byte " + std::to_string(at) + " changed");
  }
}

inline std::map<ElementType, std::size_t> countsByType(const Mesh& mesh) {
  std::map<ElementType, std::size_t> counts;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks)
      if (b.size() > 0) counts[b.type] += b.size();
  return counts;
}

// Elements per (entity, type).
inline std::map<std::pair<EntityId, ElementType>, std::size_t> countsByEntity(const Mesh& mesh) {
  std::map<std::pair<EntityId, ElementType>, std::size_t> counts;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks)
      if (b.size() > 0) counts[{id, b.type}] += b.size();
  return counts;
}

}  // namespace geomesh::testing
