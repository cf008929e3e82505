// Plugin AnalyseMeshQuality: the Jacobian determinant and the inverse condition number of the
// session's mesh elements of one dimension, logged as statistics and optionally as views.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "mesh/core/quality.h"
#include "mesh/views/plugin_functions.h"

namespace geomesh::post::plugins {
namespace {

constexpr std::string_view kPlugin = "AnalyseMeshQuality";

double det3(Vec3 a, Vec3 b, Vec3 c) {
  return dot(a, cross(b, c));
}

// The corners' Jacobian determinants of the first-order element, relative to the reference
// elements (segment [-1,1], unit right triangle and tetrahedron, squares and cubes [-1,1]);
// unsigned for lines and surfaces (a mesh alone does not say which side is up).
std::vector<double> cornerJacobians(ElementFamily family, const std::vector<Vec3>& p) {
  switch (family) {
    case ElementFamily::Line:
      return {distance(p[0], p[1]) / 2};
    case ElementFamily::Triangle:
      return {norm(cross(p[1] - p[0], p[2] - p[0]))};
    case ElementFamily::Tet:
      return {det3(p[1] - p[0], p[2] - p[0], p[3] - p[0])};
    case ElementFamily::Quad: {
      std::vector<double> j;
      for (int i = 0; i < 4; ++i)
        j.push_back(norm(cross(p[(i + 1) % 4] - p[i], p[(i + 3) % 4] - p[i])) / 4);
      return j;
    }
    case ElementFamily::Hex: {
      // Each corner with its three neighbours along the edges, in right-handed order.
      static constexpr int kEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                           {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
      std::vector<double> j;
      for (int i = 0; i < 8; ++i)
        j.push_back(det3(p[kEdges[i][0]] - p[i], p[kEdges[i][1]] - p[i], p[kEdges[i][2]] - p[i]) /
                    8);
      return j;
    }
    default:
      return {};
  }
}

// Inverse condition number of a simplex mapped to the regular one; NaN for other shapes.
double inverseConditionNumber(ElementFamily family, const std::vector<Vec3>& p) {
  if (family == ElementFamily::Triangle) return triangleSicn(p[0], p[1], p[2]);
  if (family == ElementFamily::Tet) return tetSicn(p[0], p[1], p[2], p[3]);
  if (family == ElementFamily::Line) return 1;
  return std::numeric_limits<double>::quiet_NaN();
}

struct Stats {
  double low = std::numeric_limits<double>::infinity(), high = -low, sum = 0;
  std::size_t count = 0;
  void add(double v) {
    if (std::isnan(v)) return;
    low = std::min(low, v), high = std::max(high, v), sum += v, ++count;
  }
  std::string text() const {
    char line[96];
    std::snprintf(line, sizeof line, "%8.3g, %8.3g, %8.3g", count ? low : 0,
                  count ? sum / double(count) : 0, count ? high : 0);
    return line;
  }
};

struct Measures {
  bool jacobian, icn, createView;
  Stats minJ, ratioJ, icnStats;
  View ratioView, icnView;
};

void measureElement(Measures& m, ElementFamily family, const std::vector<Vec3>& corners) {
  const ElementShape shape = ElementShape(static_cast<int>(family));  // same order
  if (m.jacobian) {
    const std::vector<double> j = cornerJacobians(family, corners);
    if (j.empty()) return;
    const auto [low, high] = std::minmax_element(j.begin(), j.end());
    const double ratio = *high != 0 ? *low / *high : 0;
    m.minJ.add(*low);
    m.ratioJ.add(ratio);
    if (m.createView)
      appendElement(m.ratioView.list(shape, FieldKind::Scalar), corners,
                    std::vector<double>(corners.size(), ratio));
  }
  if (m.icn) {
    const double icn = inverseConditionNumber(family, corners);
    m.icnStats.add(icn);
    if (m.createView && !std::isnan(icn))
      appendElement(m.icnView.list(shape, FieldKind::Scalar), corners,
                    std::vector<double>(corners.size(), icn));
  }
}

void measureDimension(const Mesh& mesh, int dim, Measures& m) {
  std::vector<Vec3> corners;
  for (const auto& [id, entity] : mesh.entities()) {
    if (id.dim != dim) continue;
    for (const ElementBlock& block : entity.blocks) {
      const ElementFamily family = elementInfo(block.type).family;
      const int count = cornerCount(ElementShape(static_cast<int>(family)));
      for (std::size_t i = 0; i < block.size(); ++i) {
        corners.clear();
        for (int k = 0; k < count; ++k)
          corners.push_back(mesh.node(block.element(i)[std::size_t(k)]));
        measureElement(m, family, corners);
      }
    }
  }
}

std::vector<int> dimensionsToAnalyse(const PluginOptions& options, const Mesh& mesh) {
  const double dim = options.number("DimensionOfElements", -1);
  if (dim == 4) return {2, 3};
  if (dim == 1 || dim == 2 || dim == 3) return {int(dim)};
  if (dim != -1) fail(kPlugin, optionText("DimensionOfElements", dim) + ": not -1, 1, 2, 3 or 4");
  for (int d = 3; d > 0; --d)
    if (mesh.elementCount(d) > 0) return {d};
  fail(kPlugin, "there is no mesh to analyse");
}

}  // namespace

void analyseMeshQuality(const PluginOptions& options, PluginContext& context) {
  const bool ige = options.number("IGEMeasure", 0) != 0;
  Measures m{options.number("JacobianDeterminant", 0) != 0,
             options.number("ICNMeasure", 0) != 0,
             options.number("CreateView", 0) != 0,
             {},
             {},
             {},
             {},
             {}};
  if (ige) context.log.warning("Plugin(AnalyseMeshQuality): the IGE measure is not computed");
  if (!m.jacobian && !m.icn) m.jacobian = !ige;
  for (int dim : dimensionsToAnalyse(options, context.mesh)) {
    measureDimension(context.mesh, dim, m);
    const std::string suffix = " " + std::to_string(dim) + "D";
    if (m.createView && m.jacobian)
      context.views.add("minJ/maxJ" + suffix).lists = std::move(m.ratioView.lists);
    if (m.createView && m.icn) context.views.add("ICN" + suffix).lists = std::move(m.icnView.lists);
    m.ratioView.lists.clear(), m.icnView.lists.clear();
  }
  if (m.jacobian) {
    context.log.info("minJ      = " + m.minJ.text() + " (min, avg, max)");
    context.log.info("minJ/maxJ = " + m.ratioJ.text() + " (worst, avg, best)");
  }
  if (m.icn) context.log.info("ICN       = " + m.icnStats.text() + " (worst, avg, best)");
}

}  // namespace geomesh::post::plugins
