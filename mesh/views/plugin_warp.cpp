// Plugin Warp: moves a view's nodes by a vector field (another view's values, or the
// surface normals scaled by the view's own values), times a factor.
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "mesh/views/plugin_functions.h"

namespace geomesh::post::plugins {
namespace {

constexpr std::string_view kPlugin = "Warp";

using Point = std::array<double, 3>;

Point key(Vec3 p) {
  return {p.x, p.y, p.z};
}

// Unit normals at the nodes of the view's surface elements, averaged over the elements
// sharing a node (by its coordinates).
std::map<Point, Vec3> nodeNormals(const View& view) {
  std::map<Point, Vec3> sums;
  for (const ElementList& list : view.lists) {
    if (shapeDimension(list.shape) != 2) continue;
    for (std::size_t e = 0; e < list.size(); ++e) {
      const Vec3 a = elementNode(list, e, 0);
      const Vec3 n = normalized(cross(elementNode(list, e, 1) - a, elementNode(list, e, 2) - a));
      for (int i = 0; i < cornerCount(list.shape); ++i) sums[key(elementNode(list, e, i))] += n;
    }
  }
  for (auto& [point, n] : sums) n = normalized(n);
  return sums;
}

const ElementList& listLike(const View& other, const ElementList& list) {
  for (const ElementList& candidate : other.lists)
    if (candidate.shape == list.shape && candidate.order == list.order &&
        candidate.size() == list.size() && candidate.kind == FieldKind::Vector)
      return candidate;
  fail(kPlugin, "OtherView \"" + other.name + "\" has no vector " + shapeLetter(list.shape) +
                    " elements laid out as View's");
}

}  // namespace

void warp(const PluginOptions& options, PluginContext& context) {
  const double factor = options.number("Factor", 1);
  View& view = context.views.at(viewIndex(options, context, kPlugin));
  const int step = stepOption(options, view, kPlugin, "TimeStep", 0, false);
  const bool byNormals = options.number("OtherView", -1) < 0;
  if (byNormals && options.number("SmoothingAngle", 180) < 180)
    context.log.warning(
        "Plugin(Warp): SmoothingAngle below 180 is not supported: normals are "
        "averaged over all the elements at a node");
  const View* other =
      byNormals ? nullptr : &context.views.at(viewIndex(options, context, kPlugin, "OtherView"));
  const std::map<Point, Vec3> normals = byNormals ? nodeNormals(view) : std::map<Point, Vec3>{};
  for (ElementList& list : view.lists) {
    if (list.size() == 0) continue;
    const ElementList* field = other ? &listLike(*other, list) : nullptr;
    if (field && step >= field->steps)
      fail(kPlugin, optionText("TimeStep", step) + ": no such step in OtherView");
    std::vector<double> moved = list.coordinates;
    for (std::size_t e = 0; e < list.size(); ++e)
      for (int n = 0; n < list.nodesPerElement; ++n) {
        const Vec3 p = elementNode(list, e, n);
        Vec3 d;
        if (field) {
          d = {field->value(e, step, n, 0), field->value(e, step, n, 1),
               field->value(e, step, n, 2)};
        } else {
          const auto it = normals.find(key(p));
          if (it == normals.end()) continue;
          d = it->second * list.value(e, std::min(step, list.steps - 1), n, 0);
        }
        const std::size_t k = 3 * (e * std::size_t(list.nodesPerElement) + std::size_t(n));
        moved[k] = p.x + factor * d.x, moved[k + 1] = p.y + factor * d.y,
        moved[k + 2] = p.z + factor * d.z;
      }
    list.coordinates = std::move(moved);
  }
}

}  // namespace geomesh::post::plugins
