// The plugin registry (one row per name) and the helpers all plugins share.
#include "mesh/views/plugins.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>

#include "mesh/views/plugin_functions.h"

namespace geomesh::post {

double PluginOptions::number(const std::string& name, double fallback) const {
  const auto it = numbers.find(name);
  return it == numbers.end() ? fallback : it->second;
}

std::string PluginOptions::text(const std::string& name, const std::string& fallback) const {
  const auto it = strings.find(name);
  return it == strings.end() ? fallback : it->second;
}

namespace {

using PluginFunction = void (*)(const PluginOptions&, PluginContext&);

struct PluginRow {
  const char* name;
  PluginFunction run;  // null: the plugin only changes the display
};

// Every plugin geomesh knows, by the reference's name.
constexpr std::array kPlugins = {
    PluginRow{"MathEval", plugins::mathEval},
    PluginRow{"ModifyComponents", plugins::modifyComponents},
    PluginRow{"CutPlane", plugins::cutPlane},
    PluginRow{"CutSphere", plugins::cutSphere},
    PluginRow{"Isosurface", plugins::isosurface},
    PluginRow{"CutGrid", plugins::cutGrid},
    PluginRow{"Integrate", plugins::integrate},
    PluginRow{"AnalyseMeshQuality", plugins::analyseMeshQuality},
    PluginRow{"Skin", plugins::skin},
    PluginRow{"Warp", plugins::warp},
    PluginRow{"NewView", plugins::newView},
    PluginRow{"ElementSize", plugins::elementSize},
    PluginRow{"Curvature", plugins::curvature},
    PluginRow{"VertexNormals", plugins::vertexNormals},
    PluginRow{"Annotate", nullptr},
    PluginRow{"DiscretizationError", nullptr},
    PluginRow{"Remove", nullptr},
};

}  // namespace

PluginOutcome runPlugin(const std::string& name, const PluginOptions& options,
                        PluginContext& context) {
  for (const PluginRow& row : kPlugins) {
    if (name != row.name) continue;
    if (!row.run) return PluginOutcome::DisplayOnly;
    row.run(options, context);
    return PluginOutcome::Ran;
  }
  return PluginOutcome::Unknown;
}

namespace plugins {

void fail(std::string_view plugin, const std::string& message) {
  throw PluginError("Plugin(" + std::string(plugin) + "): " + message);
}

std::string optionText(std::string_view option, double value) {
  std::ostringstream out;
  out << option << " = " << value;
  return out.str();
}

std::size_t viewIndex(const PluginOptions& options, const PluginContext& context,
                      std::string_view plugin, const char* option) {
  const double value = options.number(option, -1);
  const std::size_t count = context.views.size();
  if (value < 0) {
    if (count == 0) fail(plugin, optionText(option, value) + ": there is no view");
    return count - 1;
  }
  if (value != std::floor(value) || value >= double(count))
    fail(plugin,
         optionText(option, value) + ": no such view (there are " + std::to_string(count) + ")");
  return std::size_t(value);
}

int stepOption(const PluginOptions& options, const View& view, std::string_view plugin,
               const char* option, double fallback, bool allowAll) {
  const double value = options.number(option, fallback);
  if (value < 0 && allowAll) return -1;
  const int steps = std::max(view.stepCount(), 1);
  if (value < 0 || value != std::floor(value) || value >= steps)
    fail(plugin, optionText(option, value) + ": no such time step in view \"" + view.name +
                     "\" (it has " + std::to_string(steps) + ")");
  return int(value);
}

Vec3 elementNode(const ElementList& list, std::size_t e, int i) {
  const std::size_t k = 3 * (e * std::size_t(list.nodesPerElement) + std::size_t(i));
  return {list.coordinates[k], list.coordinates[k + 1], list.coordinates[k + 2]};
}

std::vector<std::vector<int>> simplexSplit(ElementShape shape) {
  switch (shape) {
    case ElementShape::Point:
      return {};
    case ElementShape::Line:
      return {{0, 1}};
    case ElementShape::Triangle:
      return {{0, 1, 2}};
    case ElementShape::Quadrangle:
      return {{0, 1, 2}, {0, 2, 3}};
    case ElementShape::Tetrahedron:
      return {{0, 1, 2, 3}};
    case ElementShape::Hexahedron:
      return {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
    case ElementShape::Prism:
      return {{0, 1, 2, 3}, {1, 2, 5, 3}, {1, 5, 4, 3}};
    case ElementShape::Pyramid:
      return {{0, 1, 2, 4}, {0, 2, 3, 4}};
  }
  return {};
}

void appendElement(ElementList& list, std::span<const Vec3> nodes, std::span<const double> values) {
  for (const Vec3& p : nodes) list.coordinates.insert(list.coordinates.end(), {p.x, p.y, p.z});
  list.values.insert(list.values.end(), values.begin(), values.end());
}

}  // namespace plugins
}  // namespace geomesh::post
