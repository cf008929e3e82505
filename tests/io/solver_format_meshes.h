// A mixed mesh and checks shared by the tests of the solver formats (Medit, UNV, Abaqus,
// Nastran, SU2, CGNS): elements placed as their reference elements, physical groups of every
// dimension, and node positions checked against each format's documented node numbering.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/formats.h"
#include "mesh/high_order/reference_element.h"

namespace geomesh::testing {

// Adds one element of `type` on `entity`: its nodes are new nodes held by the entity, at the
// reference element's nodes moved by `offset` (so that volume elements are positively oriented
// in MSH order).
inline void addReferenceElement(Mesh& mesh, EntityId entity, ElementType type, Vec3 offset) {
  const ReferenceElement& ref = referenceElement(type);
  EntityMesh& em = mesh.entity(entity);
  ElementBlock& block = em.block(type);
  for (const auto& xi : ref.xi) {
    const NodeIndex n = mesh.addNode({xi[0] + offset.x, xi[1] + offset.y, xi[2] + offset.z});
    em.nodes.push_back(n);
    block.nodes.push_back(n);
  }
}

// Volume 1: a hexahedron; volume 2: a tetrahedron and a prism; surface 3: two triangles and a
// quadrangle; curve 4: two lines; point 5: a point; surface 6, in no group: a triangle. Groups:
// volumes 10 "solid" {1} and 11 {2}, surface 20 "wall" {3}, curve 30 {4}, point 40 "tip" {5}.
inline void buildMixedMesh(Model& model, Mesh& mesh) {
  using T = ElementType;
  addReferenceElement(mesh, {3, 1}, T::Hex8, {0, 0, 0});
  addReferenceElement(mesh, {3, 2}, T::Tet4, {5, 0, 0});
  addReferenceElement(mesh, {3, 2}, T::Prism6, {10, 0, 0});
  addReferenceElement(mesh, {2, 3}, T::Triangle3, {20, 0, 0});
  addReferenceElement(mesh, {2, 3}, T::Triangle3, {22, 0, 0});
  addReferenceElement(mesh, {2, 3}, T::Quad4, {25, 0, 0});
  addReferenceElement(mesh, {1, 4}, T::Line2, {30, 0, 0});
  addReferenceElement(mesh, {1, 4}, T::Line2, {33, 0, 0});
  addReferenceElement(mesh, {0, 5}, T::Point1, {40, 0, 0});
  addReferenceElement(mesh, {2, 6}, T::Triangle3, {50, 0, 0});
  model.addPhysicalGroup({3, 10, "solid", {1}});
  model.addPhysicalGroup({3, 11, "", {2}});
  model.addPhysicalGroup({2, 20, "wall", {3}});
  model.addPhysicalGroup({1, 30, "", {4}});
  model.addPhysicalGroup({0, 40, "tip", {5}});
}

// Adds volume 7, a pyramid, to the group of volume 2.
inline void addPyramid(Model& model, Mesh& mesh) {
  addReferenceElement(mesh, {3, 7}, ElementType::Pyramid5, {15, 0, 0});
  model.addPhysicalGroup({3, 11, "", {2, 7}});
}

inline std::string writeText(const char* format, const Model& model, const Mesh& mesh,
                             const MeshWriteOptions& options = {}) {
  std::ostringstream out;
  findFormatByName(format)->write(out, model, mesh, options);
  return out.str();
}

inline std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Expects node k of `nodes` (an element's nodes in a format's order) at the centre of the
// nodes `places[k]` (0-based positions in that same order): the format's documented layout.
inline void expectLayout(const std::vector<Vec3>& nodes,
                         const std::vector<std::vector<int>>& places, const std::string& what) {
  ASSERT_EQ(nodes.size(), places.size()) << what;
  for (std::size_t k = 0; k < places.size(); ++k) {
    Vec3 centre{0, 0, 0};
    for (int c : places[k]) {
      centre.x += nodes[c].x / static_cast<double>(places[k].size());
      centre.y += nodes[c].y / static_cast<double>(places[k].size());
      centre.z += nodes[c].z / static_cast<double>(places[k].size());
    }
    EXPECT_NEAR(std::abs(nodes[k].x - centre.x) + std::abs(nodes[k].y - centre.y) +
                    std::abs(nodes[k].z - centre.z),
                0, 1e-9)
        << what << ": node " << k + 1;
  }
}

// The corners in order, then one node at the centre of each of `centres`.
inline std::vector<std::vector<int>> cornersAnd(int corners,
                                                const std::vector<std::vector<int>>& centres) {
  std::vector<std::vector<int>> places;
  for (int c = 0; c < corners; ++c) places.push_back({c});
  places.insert(places.end(), centres.begin(), centres.end());
  return places;
}

// Six times the signed volume of the tetrahedron abcd.
inline double tetVolume6(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Vec3 u{b.x - a.x, b.y - a.y, b.z - a.z}, v{c.x - a.x, c.y - a.y, c.z - a.z},
      w{d.x - a.x, d.y - a.y, d.z - a.z};
  return u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) +
         u.z * (v.x * w.y - v.y * w.x);
}

// Whether the first corners of a volume element in a format's order make a positive corner:
// corner 0 and its three neighbours (tetrahedron 0123, hexahedron 0134, prism 0123, pyramid
// 0134), the order every format here shares with MSH.
inline double cornerVolume6(ElementFamily family, const std::vector<Vec3>& n) {
  switch (family) {
    case ElementFamily::Hex:
    case ElementFamily::Pyramid:
      return tetVolume6(n[0], n[1], n[3], n[4]);
    default:
      return tetVolume6(n[0], n[1], n[2], n[3]);
  }
}

// Writing through the table to a file: the unholdable-type error must leave no file at all.
inline void expectRefusedWithoutFile(const char* format, const Model& model, const Mesh& mesh,
                                     const std::filesystem::path& path,
                                     const std::string& messagePart) {
  std::filesystem::remove(path);
  try {
    writeMeshFile(path.string(), *findFormatByName(format), model, mesh, {});
    ADD_FAILURE() << "no error writing " << path;
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(messagePart), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
}

// Per element type, the elements as lists of node coordinates in MSH order, sorted: equal for
// two meshes holding the same elements with the same node orders.
inline std::map<ElementType, std::vector<std::vector<double>>> elementsByType(const Mesh& mesh) {
  std::map<ElementType, std::vector<std::vector<double>>> out;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks)
      for (std::size_t i = 0; i < b.size(); ++i) {
        std::vector<double> coords;
        for (NodeIndex n : b.element(i))
          for (double v : {mesh.node(n).x, mesh.node(n).y, mesh.node(n).z})
            coords.push_back(std::round(v * 1e9) / 1e9);
        out[b.type].push_back(coords);
      }
  for (auto& [type, list] : out) std::sort(list.begin(), list.end());
  return out;
}

}  // namespace geomesh::testing
