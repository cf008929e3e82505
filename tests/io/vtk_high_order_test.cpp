// VTK output of second-order elements: each VTK node sits where VTK's parametric coordinates
// of that node put it; types VTK cannot hold are refused; the order limits of the format table.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/formats.h"
#include "mesh/high_order/reference_element.h"

namespace geomesh {
namespace {

using Coords = std::vector<std::array<double, 3>>;

// VTK's parametric coordinates of the nodes of its quadratic cells, in VTK's node order (the
// tables of VTK's cell classes). VTK's parametric spaces are [0, 1] in every direction; the
// pyramid's apex is at (0, 0, 1).
struct VtkCellCoords {
  ElementType type;
  int vtkType;
  Coords pcoords;
};

std::vector<VtkCellCoords> vtkQuadraticCells() {
  const Coords hex20 = {{0, 0, 0},   {1, 0, 0},   {1, 1, 0},   {0, 1, 0},   {0, 0, 1},
                        {1, 0, 1},   {1, 1, 1},   {0, 1, 1},   {.5, 0, 0},  {1, .5, 0},
                        {.5, 1, 0},  {0, .5, 0},  {.5, 0, 1},  {1, .5, 1},  {.5, 1, 1},
                        {0, .5, 1},  {0, 0, .5},  {1, 0, .5},  {1, 1, .5},  {0, 1, .5}};
  Coords hex27 = hex20;
  hex27.insert(hex27.end(), {{0, .5, .5},
                             {1, .5, .5},
                             {.5, 0, .5},
                             {.5, 1, .5},
                             {.5, .5, 0},
                             {.5, .5, 1},
                             {.5, .5, .5}});
  const Coords wedge15 = {{0, 0, 0},  {1, 0, 0},  {0, 1, 0},  {0, 0, 1},  {1, 0, 1},
                          {0, 1, 1},  {.5, 0, 0}, {.5, .5, 0}, {0, .5, 0}, {.5, 0, 1},
                          {.5, .5, 1}, {0, .5, 1}, {0, 0, .5}, {1, 0, .5}, {0, 1, .5}};
  Coords wedge18 = wedge15;
  wedge18.insert(wedge18.end(), {{.5, 0, .5}, {.5, .5, .5}, {0, .5, .5}});
  return {
      {ElementType::Line3, 21, {{0, 0, 0}, {1, 0, 0}, {.5, 0, 0}}},
      {ElementType::Triangle6, 22,
       {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {.5, 0, 0}, {.5, .5, 0}, {0, .5, 0}}},
      {ElementType::Quad8, 23,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {.5, 0, 0}, {1, .5, 0}, {.5, 1, 0},
        {0, .5, 0}}},
      {ElementType::Quad9, 28,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {.5, 0, 0}, {1, .5, 0}, {.5, 1, 0},
        {0, .5, 0}, {.5, .5, 0}}},
      {ElementType::Tet10, 24,
       {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {.5, 0, 0}, {.5, .5, 0}, {0, .5, 0},
        {0, 0, .5}, {.5, 0, .5}, {0, .5, .5}}},
      {ElementType::Hex20, 25, hex20},
      {ElementType::Hex27, 29, hex27},
      {ElementType::Prism15, 26, wedge15},
      {ElementType::Prism18, 32, wedge18},
      {ElementType::Pyramid13, 27,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {.5, 0, 0}, {1, .5, 0},
        {.5, 1, 0}, {0, .5, 0}, {0, 0, .5}, {1, 0, .5}, {1, 1, .5}, {0, 1, .5}}},
  };
}

// A point of VTK's parametric space in the MSH reference space of the same family.
std::array<double, 3> toMshReference(ElementFamily f, const std::array<double, 3>& p) {
  const double r = p[0], s = p[1], t = p[2];
  switch (f) {
    case ElementFamily::Line:
    case ElementFamily::Quad:
    case ElementFamily::Hex: return {2 * r - 1, f == ElementFamily::Line ? 0 : 2 * s - 1,
                                     f == ElementFamily::Hex ? 2 * t - 1 : 0};
    case ElementFamily::Prism: return {r, s, 2 * t - 1};
    case ElementFamily::Pyramid: return {(2 * r - 1) * (1 - t), (2 * s - 1) * (1 - t), t};
    default: return {r, s, t};
  }
}

Vec3 placed(const std::array<double, 3>& xi) {
  return {1.0 + 2.0 * xi[0] + 0.3 * xi[1] + 0.1 * xi[2],
          -2.0 + 0.2 * xi[0] + 1.5 * xi[1] + 0.4 * xi[2],
          3.0 + 0.1 * xi[0] - 0.3 * xi[1] + 1.2 * xi[2]};
}

// One element of `type` on entity (dim, 1), its nodes at the image of the reference nodes.
Mesh oneElement(ElementType type) {
  Mesh mesh;
  EntityMesh& em = mesh.entity({dimension(type), 1});
  ElementBlock& block = em.block(type);
  for (const std::array<double, 3>& xi : referenceElement(type).xi) {
    const NodeIndex n = mesh.addNode(placed(xi));
    em.nodes.push_back(n);
    block.nodes.push_back(n);
  }
  return mesh;
}

struct ParsedVtk {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> cells;
  std::vector<int> types;
};

ParsedVtk parse(const std::string& text) {
  ParsedVtk out;
  std::istringstream in(text);
  std::string word;
  while (in >> word) {
    std::size_t n = 0, size = 0;
    if (word == "POINTS") {
      in >> n >> word;
      for (std::size_t i = 0; i < n; ++i) {
        Vec3 p;
        in >> p.x >> p.y >> p.z;
        out.points.push_back(p);
      }
    } else if (word == "CELLS") {
      in >> n >> size;
      for (std::size_t i = 0; i < n; ++i) {
        int count = 0;
        in >> count;
        std::vector<int> cell(static_cast<std::size_t>(count));
        for (int& c : cell) in >> c;
        out.cells.push_back(cell);
      }
    } else if (word == "CELL_TYPES") {
      in >> n;
      out.types.resize(n);
      for (int& t : out.types) in >> t;
    }
  }
  return out;
}

std::string vtkOf(const Mesh& mesh) {
  std::ostringstream out;
  findFormatByName("vtk")->write(out, Model{}, mesh, {true, false});
  return out.str();
}

TEST(VtkHighOrder, EachVtkNodeSitsWhereVtkPlacesIt) {
  for (const VtkCellCoords& cell : vtkQuadraticCells()) {
    const ParsedVtk vtk = parse(vtkOf(oneElement(cell.type)));
    const std::string name = elementName(cell.type);
    ASSERT_EQ(vtk.cells.size(), 1u) << name;
    ASSERT_EQ(vtk.types, std::vector<int>{cell.vtkType}) << name;
    ASSERT_EQ(vtk.cells[0].size(), cell.pcoords.size()) << name;
    for (std::size_t k = 0; k < cell.pcoords.size(); ++k) {
      const Vec3 expected = placed(toMshReference(family(cell.type), cell.pcoords[k]));
      const Vec3 actual = vtk.points.at(static_cast<std::size_t>(vtk.cells[0][k]));
      EXPECT_LT(distance(expected, actual), 1e-12) << name << ": VTK node " << k;
    }
  }
}

TEST(VtkHighOrder, UsesEveryNodeOnce) {
  for (const VtkCellCoords& cell : vtkQuadraticCells()) {
    const ParsedVtk vtk = parse(vtkOf(oneElement(cell.type)));
    std::vector<int> nodes = vtk.cells.at(0);
    std::sort(nodes.begin(), nodes.end());
    for (std::size_t k = 0; k < nodes.size(); ++k)
      EXPECT_EQ(nodes[k], static_cast<int>(k)) << elementName(cell.type);
  }
}

TEST(VtkHighOrder, RefusesTypesVtkCannotHold) {
  for (const ElementTypeInfo& info : kElementTypes) {
    if (info.order <= 2 && info.type != ElementType::Pyramid14) continue;
    try {
      vtkOf(oneElement(info.type));
      ADD_FAILURE() << info.name << " was written";
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(info.name), std::string::npos) << message;
      if (info.order > 2) {
        EXPECT_NE(message.find("up to order 2"), std::string::npos) << message;
      }
    }
  }
}

TEST(VtkHighOrder, FormatsTellTheOrdersTheyHold) {
  const MeshFormat& vtk = *findFormatByName("vtk");
  const MeshFormat& msh41 = *findFormatByName("msh41");
  const MeshFormat& msh22 = *findFormatByName("msh22");
  EXPECT_EQ(vtk.maxOrder, 2);
  EXPECT_EQ(msh41.maxOrder, 4);
  EXPECT_EQ(msh22.maxOrder, 4);
  EXPECT_EQ(orderUnsupportedReason(vtk, 1), "");
  EXPECT_EQ(orderUnsupportedReason(vtk, 2), "");
  EXPECT_EQ(orderUnsupportedReason(vtk, 3), "vtk files hold elements up to order 2");
  EXPECT_EQ(orderUnsupportedReason(msh41, 4), "");
  EXPECT_EQ(orderUnsupportedReason(msh22, 4), "");
  EXPECT_EQ(orderUnsupportedReason(msh41, 5), "msh41 files hold elements up to order 4");
}

}  // namespace
}  // namespace geomesh
