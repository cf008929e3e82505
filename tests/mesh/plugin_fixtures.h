// Shared data for the plugin tests: views on cubes of tetrahedra, a formula compiler.
#pragma once

#include <cctype>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/sizes/named_formula.h"
#include "mesh/views/plugins.h"

namespace geomesh::post::testing {

// Compiles formulas as a session does.
inline CompiledFormula compileWithMathExpression(const std::string& text,
                                                 const std::vector<std::string>& variables) {
  return compileNamedFormula(text, variables);
}

// A scalar view on the cube [0, n]^3 / n split into n^3 cubes of 6 tetrahedra each, with the
// values f(node).
inline void addTetCube(View& view, int n, const std::function<double(Vec3)>& f) {
  static constexpr int kTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                      {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  static constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  ElementList& list = view.list(ElementShape::Tetrahedron, FieldKind::Scalar);
  const double h = 1.0 / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& tet : kTets)
          for (int c : tet) {
            const Vec3 p{(i + kCorner[c][0]) * h, (j + kCorner[c][1]) * h, (k + kCorner[c][2]) * h};
            list.coordinates.insert(list.coordinates.end(), {p.x, p.y, p.z});
            list.values.push_back(f(p));
          }
}

// Area of the triangles and quadrangles of a view (quadrangles as two triangles).
inline double surfaceArea(const View& view) {
  double area = 0;
  for (const ElementList& list : view.lists) {
    if (list.shape != ElementShape::Triangle && list.shape != ElementShape::Quadrangle) continue;
    for (std::size_t e = 0; e < list.size(); ++e) {
      const auto node = [&](int i) {
        const std::size_t k = 3 * (e * std::size_t(list.nodesPerElement) + std::size_t(i));
        return Vec3{list.coordinates[k], list.coordinates[k + 1], list.coordinates[k + 2]};
      };
      area += norm(cross(node(1) - node(0), node(2) - node(0))) / 2;
      if (list.shape == ElementShape::Quadrangle)
        area += norm(cross(node(2) - node(0), node(3) - node(0))) / 2;
    }
  }
  return area;
}

// The linear field the plugin tests cut, integrate and evaluate.
inline double linearField(Vec3 p) { return p.x + 2 * p.y + 3 * p.z; }

// Node i of element e of a list.
inline Vec3 nodeOf(const ElementList& list, std::size_t e, int i) {
  const std::size_t k = 3 * (e * std::size_t(list.nodesPerElement) + std::size_t(i));
  return {list.coordinates[k], list.coordinates[k + 1], list.coordinates[k + 2]};
}

}  // namespace geomesh::post::testing
