// Plugin Integrate: the integral of a view over its elements (flux through surfaces and
// circulation along lines for vectors), or of each node's values over time.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "stdlib/clamped_integer.h"
#include "mesh/views/plugin_functions.h"

namespace geomesh::post::plugins {
namespace {

constexpr std::string_view kPlugin = "Integrate";

// Components of one list's integral at one step, and how many there are.
struct Sum {
  std::array<double, 9> value{};
  int components = 0;
};

// The mean over the corners `s` of component c at a step.
double cornerMean(const ElementList& list, std::size_t e, int step, const std::vector<int>& s,
                  int c) {
  double sum = 0;
  for (int corner : s) sum += list.value(e, step, corner, c);
  return sum / double(s.size());
}

Vec3 cornerMeanVector(const ElementList& list, std::size_t e, int step, const std::vector<int>& s) {
  return {cornerMean(list, e, step, s, 0), cornerMean(list, e, step, s, 1),
          cornerMean(list, e, step, s, 2)};
}

// Length, area or volume of a simplex of the element's corners.
double simplexMeasure(const ElementList& list, std::size_t e, const std::vector<int>& s) {
  const Vec3 a = elementNode(list, e, s[0]);
  if (s.size() == 2) return distance(a, elementNode(list, e, s[1]));
  const Vec3 u = elementNode(list, e, s[1]) - a, v = elementNode(list, e, s[2]) - a;
  if (s.size() == 3) return norm(cross(u, v)) / 2;
  return std::abs(dot(cross(u, v), elementNode(list, e, s[3]) - a)) / 6;
}

// The integral over a simplex of linear data: scalars exactly; vectors as circulation
// (lines), flux along the corner order's normal (triangles), or component by component.
void addSimplex(const ElementList& list, std::size_t e, int step, const std::vector<int>& s,
                Sum& sum) {
  const int components = list.components();
  const bool oriented = components == 3 && (s.size() == 2 || s.size() == 3);
  sum.components = oriented ? 1 : components;
  if (oriented) {
    const Vec3 v = cornerMeanVector(list, e, step, s);
    const Vec3 a = elementNode(list, e, s[0]), u = elementNode(list, e, s[1]) - a;
    const Vec3 weighted = s.size() == 2 ? u : cross(u, elementNode(list, e, s[2]) - a) / 2;
    sum.value[0] += dot(v, weighted);
    return;
  }
  const double measure = simplexMeasure(list, e, s);
  for (int c = 0; c < components; ++c)
    sum.value[std::size_t(c)] += measure * cornerMean(list, e, step, s, c);
}

Sum integrateList(const ElementList& list, int step) {
  Sum sum;
  sum.components = list.components();
  const std::vector<std::vector<int>> parts = simplexSplit(list.shape);
  for (std::size_t e = 0; e < list.size(); ++e) {
    if (list.shape == ElementShape::Point) {
      for (int c = 0; c < list.components(); ++c)
        sum.value[std::size_t(c)] += list.value(e, step, 0, c);
      continue;
    }
    for (const std::vector<int>& part : parts) addSimplex(list, e, step, part, sum);
  }
  return sum;
}

Vec3 boxCenter(const View& view) {
  Vec3 low{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3 high = -low;
  for (const ElementList& list : view.lists)
    for (std::size_t k = 0; k + 2 < list.coordinates.size(); k += 3) {
      low = {std::min(low.x, list.coordinates[k]), std::min(low.y, list.coordinates[k + 1]),
             std::min(low.z, list.coordinates[k + 2])};
      high = {std::max(high.x, list.coordinates[k]), std::max(high.y, list.coordinates[k + 1]),
              std::max(high.z, list.coordinates[k + 2])};
    }
  return low.x <= high.x ? (low + high) / 2 : Vec3{};
}

// The integral over space at every step: one point at the middle of the view's box.
void integrateOverSpace(const View& view, int dimension, View& result, MessageSink& log) {
  const int steps = std::max(view.stepCount(), 1);
  std::vector<Sum> sums(static_cast<std::size_t>(steps));
  for (const ElementList& list : view.lists) {
    if (list.size() == 0 || (dimension >= 0 && shapeDimension(list.shape) != dimension)) continue;
    for (int s = 0; s < std::min(steps, list.steps); ++s) {
      const Sum part = integrateList(list, s);
      Sum& total = sums[std::size_t(s)];
      if (total.components != 0 && total.components != part.components)
        fail(kPlugin, "the view mixes scalar and vector or tensor integrals");
      total.components = part.components;
      for (std::size_t c = 0; c < 9; ++c) total.value[c] += part.value[c];
    }
  }
  const int components = std::max(sums[0].components, 1);
  ElementList& out = result.list(ElementShape::Point, components == 1   ? FieldKind::Scalar
                                                      : components == 3 ? FieldKind::Vector
                                                                        : FieldKind::Tensor);
  out.steps = steps;
  std::vector<double> values;
  for (int s = 0; s < steps; ++s) {
    const Sum& sum = sums[std::size_t(s)];
    values.insert(values.end(), sum.value.begin(), sum.value.begin() + components);
    log.info("Plugin(Integrate): step " + std::to_string(s) +
             ": integral = " + std::to_string(sum.value[0]));
  }
  const Vec3 center = boxCenter(view);
  appendElement(out, std::span<const Vec3>(&center, 1), values);
}

// Each node's values integrated over time by the trapezoidal rule from step `first`:
// step k of the result holds the integral from time[first] to time[first + k].
void integrateOverTime(const View& view, int first, View& result) {
  const auto time = [&](int s) {
    return std::size_t(s) < view.times.size() ? view.times[std::size_t(s)] : double(s);
  };
  for (const ElementList& list : view.lists) {
    if (list.size() == 0) continue;
    if (list.components() != 1) fail(kPlugin, "only scalar views are integrated over time");
    if (first >= list.steps) fail(kPlugin, optionText("OverTime", first) + ": no such step");
    ElementList& out = result.list(list.shape, FieldKind::Scalar, list.order);
    out.nodesPerElement = list.nodesPerElement;
    out.steps = list.steps - first;
    out.coordinates = list.coordinates;
    for (std::size_t e = 0; e < list.size(); ++e)
      for (int s = first; s < list.steps; ++s)
        for (int n = 0; n < list.nodesPerElement; ++n) {
          double sum = 0;
          for (int k = first; k < s; ++k)
            sum +=
                (time(k + 1) - time(k)) * (list.value(e, k, n, 0) + list.value(e, k + 1, n, 0)) / 2;
          out.values.push_back(sum);
        }
  }
}

}  // namespace

void integrate(const PluginOptions& options, PluginContext& context) {
  const std::size_t index = viewIndex(options, context, kPlugin);
  const View& view = context.views.at(index);
  const double overTime = options.number("OverTime", -1);
  const double dimension = options.number("Dimension", -1);
  if (dimension > 3) fail(kPlugin, optionText("Dimension", dimension) + ": not 0 to 3");
  View result;
  if (overTime > -1)
    integrateOverTime(view, clampedInteger<int>(overTime), result);
  else
    integrateOverSpace(view, clampedInteger<int>(dimension), result, context.log);
  View& added = context.views.add(view.name + "_Integrate");
  added.lists = std::move(result.lists);
  if (overTime <= -1) added.times = context.views.at(index).times;
}

}  // namespace geomesh::post::plugins
