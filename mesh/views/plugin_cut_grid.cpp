// Plugin CutGrid: a view sampled on a regular grid of points spanned by three points,
// as quadrangles, lines or points (0 where the grid leaves the view).
#include <algorithm>
#include <array>
#include <vector>

#include "mesh/views/plugin_functions.h"
#include "mesh/views/view_probe.h"

namespace geomesh::post::plugins {
namespace {

constexpr std::string_view kPlugin = "CutGrid";

struct Grid {
  Vec3 origin, u, v;  // u, v: the whole span along each axis
  int nu, nv;
  Vec3 point(int i, int j) const {
    const double s = nu > 1 ? double(i) / (nu - 1) : 0, t = nv > 1 ? double(j) / (nv - 1) : 0;
    return origin + s * u + t * v;
  }
};

int pointCount(const PluginOptions& options, const char* option) {
  const double n = options.number(option, 20);
  if (!(n >= 1)) fail(kPlugin, optionText(option, n) + ": at least 1 point");
  // A grid of 1e8 points is far beyond what a view can show; refused rather than exhaust memory.
  if (n > 1e4) fail(kPlugin, optionText(option, n) + ": at most 10000 points");
  return int(n);
}

// The values of every grid point: steps x points x components.
std::vector<double> sampleGrid(const View& view, const Grid& grid, int components, int steps) {
  std::vector<double> values;
  for (int s = 0; s < steps; ++s) {
    const ViewProbe probe(view, s);
    for (int j = 0; j < grid.nv; ++j)
      for (int i = 0; i < grid.nu; ++i) {
        const auto sample = probe.components(grid.point(i, j));
        for (int c = 0; c < components; ++c)
          values.push_back(sample ? (*sample)[std::size_t(c)] : 0.0);
      }
  }
  return values;
}

// The grid's elements: quadrangles, lines along the one long axis, or points.
std::vector<std::vector<int>> gridElements(const Grid& grid, bool connect) {
  const auto id = [&](int i, int j) { return j * grid.nu + i; };
  std::vector<std::vector<int>> elements;
  if (connect && grid.nu > 1 && grid.nv > 1) {
    for (int j = 0; j + 1 < grid.nv; ++j)
      for (int i = 0; i + 1 < grid.nu; ++i)
        elements.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  } else if (connect && (grid.nu > 1 || grid.nv > 1)) {
    for (int k = 0; k + 1 < grid.nu * grid.nv; ++k) elements.push_back({k, k + 1});
  } else {
    for (int k = 0; k < grid.nu * grid.nv; ++k) elements.push_back({k});
  }
  return elements;
}

}  // namespace

void cutGrid(const PluginOptions& options, PluginContext& context) {
  const auto at = [&](const char* x, const char* y, const char* z, Vec3 fallback) {
    return Vec3{options.number(x, fallback.x), options.number(y, fallback.y),
                options.number(z, fallback.z)};
  };
  const Vec3 p0 = at("X0", "Y0", "Z0", {0, 0, 0});
  const Grid grid{p0, at("X1", "Y1", "Z1", {1, 0, 0}) - p0, at("X2", "Y2", "Z2", {0, 1, 0}) - p0,
                  pointCount(options, "NumPointsU"), pointCount(options, "NumPointsV")};
  if (double(grid.nu) * double(grid.nv) > 4e6)
    fail(kPlugin, "NumPointsU x NumPointsV = " + std::to_string(grid.nu) + " x " +
                      std::to_string(grid.nv) + ": at most 4e6 points");
  const std::size_t index = viewIndex(options, context, kPlugin);
  const View& view = context.views.at(index);
  FieldKind kind = FieldKind::Scalar;
  for (const ElementList& list : view.lists)
    if (list.size() > 0) kind = std::max(kind, list.kind);
  const int components = componentCount(kind), steps = std::max(view.stepCount(), 1);
  const std::vector<double> values = sampleGrid(view, grid, components, steps);
  const std::size_t points = std::size_t(grid.nu) * std::size_t(grid.nv);
  View result;
  for (const std::vector<int>& element :
       gridElements(grid, options.number("ConnectPoints", 1) != 0)) {
    const ElementShape shape = element.size() == 4   ? ElementShape::Quadrangle
                               : element.size() == 2 ? ElementShape::Line
                                                     : ElementShape::Point;
    ElementList& out = result.list(shape, kind);
    out.steps = steps;
    std::vector<Vec3> nodes;
    std::vector<double> data;
    for (int k : element) nodes.push_back(grid.point(k % grid.nu, k / grid.nu));
    for (int s = 0; s < steps; ++s)
      for (int k : element)
        for (int c = 0; c < components; ++c)
          data.push_back(
              values[(std::size_t(s) * points + std::size_t(k)) * std::size_t(components) +
                     std::size_t(c)]);
    appendElement(out, nodes, data);
  }
  View& added = context.views.add(view.name + "_CutGrid");
  added.lists = std::move(result.lists);
  added.times = context.views.at(index).times;
}

}  // namespace geomesh::post::plugins
