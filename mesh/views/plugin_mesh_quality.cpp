// Plugin AnalyseMeshQuality: the Jacobian determinant, the inverse gradient error and the
// inverse condition number of the session's mesh elements of one dimension, logged as
// statistics and optionally as views.
#include <algorithm>
#include <array>
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

// The scaled Jacobian at each corner (the determinant of the unit edge vectors leaving it);
// for quadrangles, relative to the normal the diagonals give.
std::vector<double> cornerScaledJacobians(ElementFamily family, const std::vector<Vec3>& p) {
  std::vector<double> s;
  if (family == ElementFamily::Quad) {
    const Vec3 normal = cross(p[2] - p[0], p[3] - p[1]);
    for (int i = 0; i < 4; ++i) {
      const Vec3 a = p[(i + 1) % 4] - p[i], b = p[(i + 3) % 4] - p[i];
      s.push_back(dot(cross(a, b), normal) / (norm(a) * norm(b) * norm(normal)));
    }
    return s;
  }
  static constexpr int kEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                       {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  for (int i = 0; i < 8; ++i) {
    const Vec3 a = p[kEdges[i][0]] - p[i], b = p[kEdges[i][1]] - p[i], c = p[kEdges[i][2]] - p[i];
    s.push_back(det3(a, b, c) / (norm(a) * norm(b) * norm(c)));
  }
  return s;
}

// Sum of the sines of the angles of a triangle, 1 for the equilateral one.
double triangleIge(const std::vector<Vec3>& p) {
  const double twiceArea = norm(cross(p[1] - p[0], p[2] - p[0]));
  double sines = 0;
  for (int i = 0; i < 3; ++i)
    sines += twiceArea / (distance(p[i], p[(i + 1) % 3]) * distance(p[i], p[(i + 2) % 3]));
  return sines / (1.5 * std::sqrt(3.0));
}

// The tetrahedron's |det| over the product of the edge lengths of each of its 12 paths through
// the four corners, summed; 1 for the regular tetrahedron.
double tetIge(const std::vector<Vec3>& p) {
  const double det = std::abs(det3(p[1] - p[0], p[2] - p[0], p[3] - p[0]));
  std::array<int, 4> path{0, 1, 2, 3};
  double sum = 0;
  do {
    if (path[0] > path[3]) continue;  // each path once, not also backwards
    sum += det / (distance(p[path[0]], p[path[1]]) * distance(p[path[1]], p[path[2]]) *
                  distance(p[path[2]], p[path[3]]));
  } while (std::next_permutation(path.begin(), path.end()));
  return sum * std::sqrt(2.0) / 12;
}

// The inverse gradient error of a first-order element, as the reference computes it (checked
// against Gmsh 4.15): an angle measure for simplices, the smallest scaled Jacobian for
// quadrangles and hexahedra (0 when the corners disagree in sign); NaN for other shapes.
double inverseGradientError(ElementFamily family, const std::vector<Vec3>& p) {
  if (family == ElementFamily::Triangle) return triangleIge(p);
  if (family == ElementFamily::Tet) return tetIge(p);
  if (family == ElementFamily::Line) return 1;
  if (family != ElementFamily::Quad && family != ElementFamily::Hex)
    return std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> s = cornerScaledJacobians(family, p);
  const auto [low, high] = std::minmax_element(s.begin(), s.end());
  if (*low > 0) return *low;
  return *high < 0 ? -*high : 0;
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
  bool jacobian, ige, icn, createView;
  Stats minJ, ratioJ, igeStats, icnStats;
  View ratioView, igeView, icnView;
};

// Adds one element's value of a measure to its statistics and view.
void record(Stats& stats, View& view, bool createView, ElementShape shape,
            const std::vector<Vec3>& corners, double value) {
  stats.add(value);
  if (createView && !std::isnan(value))
    appendElement(view.list(shape, FieldKind::Scalar), corners,
                  std::vector<double>(corners.size(), value));
}

void measureElement(Measures& m, ElementFamily family, const std::vector<Vec3>& corners) {
  const ElementShape shape = ElementShape(static_cast<int>(family));  // same order
  const std::vector<double> j =
      m.jacobian ? cornerJacobians(family, corners) : std::vector<double>{};
  if (!j.empty()) {
    const auto [low, high] = std::minmax_element(j.begin(), j.end());
    const double ratio = *high != 0 ? *low / *high : 0;
    m.minJ.add(*low);
    m.ratioJ.add(ratio);
    if (m.createView)
      appendElement(m.ratioView.list(shape, FieldKind::Scalar), corners,
                    std::vector<double>(corners.size(), ratio));
  }
  if (m.ige)
    record(m.igeStats, m.igeView, m.createView, shape, corners,
           inverseGradientError(family, corners));
  if (m.icn)
    record(m.icnStats, m.icnView, m.createView, shape, corners,
           inverseConditionNumber(family, corners));
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
  Measures m{};
  m.jacobian = options.number("JacobianDeterminant", 0) != 0;
  m.ige = options.number("IGEMeasure", 0) != 0;
  m.icn = options.number("ICNMeasure", 0) != 0;
  m.createView = options.number("CreateView", 0) != 0;
  if (!m.jacobian && !m.ige && !m.icn) m.jacobian = true;
  for (int dim : dimensionsToAnalyse(options, context.mesh)) {
    measureDimension(context.mesh, dim, m);
    const std::string suffix = " " + std::to_string(dim) + "D";
    if (m.createView && m.jacobian)
      context.views.add("minJ/maxJ" + suffix).lists = std::move(m.ratioView.lists);
    if (m.createView && m.ige) context.views.add("IGE" + suffix).lists = std::move(m.igeView.lists);
    if (m.createView && m.icn) context.views.add("ICN" + suffix).lists = std::move(m.icnView.lists);
    m.ratioView.lists.clear(), m.igeView.lists.clear(), m.icnView.lists.clear();
  }
  if (m.jacobian) {
    context.log.info("minJ      = " + m.minJ.text() + " (min, avg, max)");
    context.log.info("minJ/maxJ = " + m.ratioJ.text() + " (worst, avg, best)");
  }
  if (m.ige) context.log.info("IGE       = " + m.igeStats.text() + " (worst, avg, best)");
  if (m.icn) context.log.info("ICN       = " + m.icnStats.text() + " (worst, avg, best)");
}

}  // namespace geomesh::post::plugins
