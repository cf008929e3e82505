// Plugins CutPlane, CutSphere and Isosurface: a view cut where a level function is zero,
// element by element split into simplices (tetrahedra give triangles or quadrangles,
// triangles give lines, lines give points), values interpolated linearly on the cut.
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "mesh/views/plugin_functions.h"

namespace geomesh::post::plugins {
namespace {

// A point of the cut: on the edge from corner a to corner b, at parameter t.
struct EdgePoint {
  int a, b;
  double t;
};

EdgePoint crossing(int a, int b, const std::vector<double>& levels) {
  const double la = levels[std::size_t(a)], lb = levels[std::size_t(b)];
  return {a, b, la / (la - lb)};
}

// The cut of one simplex (corners `s`, level at each corner of the element in `levels`):
// a polygon of 1 (line), 2 (triangle), 3 or 4 (tetrahedron) points; empty when not cut.
std::vector<EdgePoint> cutSimplex(const std::vector<int>& s, const std::vector<double>& levels) {
  std::vector<int> above, below;
  for (int corner : s) (levels[std::size_t(corner)] > 0 ? above : below).push_back(corner);
  if (above.empty() || below.empty()) return {};
  if (s.size() == 4 && above.size() == 2)
    return {crossing(above[0], below[0], levels), crossing(above[0], below[1], levels),
            crossing(above[1], below[1], levels), crossing(above[1], below[0], levels)};
  const bool loneAbove = above.size() == 1;
  const int lone = loneAbove ? above[0] : below[0];
  std::vector<EdgePoint> cut;
  for (int other : loneAbove ? below : above) cut.push_back(crossing(lone, other, levels));
  return cut;
}

// Where the values on a cut come from: a list laid out as the cut one, at some steps.
struct ValueSource {
  const ElementList* list;
  int firstStep, stepCount;
};

using LevelFunction = std::function<double(const ElementList&, std::size_t, int)>;

ElementShape cutShape(int dimension, std::size_t points) {
  if (dimension == 3) return points == 4 ? ElementShape::Quadrangle : ElementShape::Triangle;
  return dimension == 2 ? ElementShape::Line : ElementShape::Point;
}

bool sameNode(const EdgePoint& p, const EdgePoint& q, const ElementList& list, std::size_t e) {
  const Vec3 a = elementNode(list, e, p.a), b = elementNode(list, e, p.b);
  const Vec3 c = elementNode(list, e, q.a), d = elementNode(list, e, q.b);
  return distance(a + p.t * (b - a), c + q.t * (d - c)) == 0;
}

// Drops repeated points (a cut through corners); false when too few are left.
bool removeRepeats(std::vector<EdgePoint>& cut, const ElementList& list, std::size_t e) {
  std::vector<EdgePoint> kept;
  for (const EdgePoint& p : cut) {
    bool repeated = false;
    for (const EdgePoint& q : kept) repeated = repeated || sameNode(p, q, list, e);
    if (!repeated) kept.push_back(p);
  }
  cut = kept;
  const int dimension = shapeDimension(list.shape);
  return dimension == 3 ? cut.size() >= 3 : cut.size() == std::size_t(dimension);
}

void appendCut(const std::vector<EdgePoint>& cut, const ElementList& list, std::size_t e,
               const ValueSource& source, View& result) {
  const ElementList& values = *source.list;
  ElementList& out = result.list(cutShape(shapeDimension(list.shape), cut.size()), values.kind, 1);
  out.steps = source.stepCount;
  std::vector<Vec3> nodes;
  for (const EdgePoint& p : cut) {
    const Vec3 a = elementNode(list, e, p.a), b = elementNode(list, e, p.b);
    nodes.push_back(a + p.t * (b - a));
  }
  std::vector<double> data;
  for (int s = source.firstStep; s < source.firstStep + source.stepCount; ++s)
    for (const EdgePoint& p : cut)
      for (int c = 0; c < values.components(); ++c)
        data.push_back((1 - p.t) * values.value(e, s, p.a, c) + p.t * values.value(e, s, p.b, c));
  appendElement(out, nodes, data);
}

// Cuts every element of `list` where `level` is zero, adding the pieces to `result`.
void cutList(const ElementList& list, const LevelFunction& level, const ValueSource& source,
             View& result) {
  const std::vector<std::vector<int>> parts = simplexSplit(list.shape);
  const int corners = cornerCount(list.shape);
  std::vector<double> levels(static_cast<std::size_t>(corners));
  for (std::size_t e = 0; e < list.size(); ++e) {
    for (int i = 0; i < corners; ++i) levels[std::size_t(i)] = level(list, e, i);
    for (const std::vector<int>& part : parts) {
      std::vector<EdgePoint> cut = cutSimplex(part, levels);
      if (!cut.empty() && removeRepeats(cut, list, e)) appendCut(cut, list, e, source, result);
    }
  }
}

void rejectExtractVolume(const PluginOptions& options, std::string_view plugin) {
  const double extract = options.number("ExtractVolume", 0);
  if (extract != 0)
    fail(plugin, optionText("ExtractVolume", extract) + ": extracting volumes is not supported");
}

// Cuts the whole view (all steps) by a geometric level function: CutPlane, CutSphere.
void cutByGeometry(const PluginOptions& options, PluginContext& context, std::string_view plugin,
                   const std::function<double(Vec3)>& level) {
  rejectExtractVolume(options, plugin);
  const std::size_t index = viewIndex(options, context, plugin);
  const View& view = context.views.at(index);
  View result;
  const LevelFunction nodeLevel = [&](const ElementList& list, std::size_t e, int i) {
    return level(elementNode(list, e, i));
  };
  for (const ElementList& list : view.lists)
    if (list.size() > 0) cutList(list, nodeLevel, {&list, 0, list.steps}, result);
  View& added = context.views.add(view.name + "_Levelset");
  added.lists = std::move(result.lists);
  added.times = context.views.at(index).times;
}

// The scalar of a node at a step: the value, or the norm of a vector or tensor.
double nodeScalar(const ElementList& list, std::size_t e, int step, int node) {
  if (list.components() == 1) return list.value(e, step, node, 0);
  double sum = 0;
  for (int c = 0; c < list.components(); ++c) sum += std::pow(list.value(e, step, node, c), 2);
  return std::sqrt(sum);
}

const ElementList& listLike(const View& other, const ElementList& list) {
  for (const ElementList& candidate : other.lists)
    if (candidate.shape == list.shape && candidate.order == list.order &&
        candidate.size() == list.size())
      return candidate;
  throw PluginError("Plugin(Isosurface): OtherView \"" + other.name + "\" has no " +
                    shapeLetter(list.shape) + " elements laid out as View's");
}

}  // namespace

void cutPlane(const PluginOptions& options, PluginContext& context) {
  const double a = options.number("A", 1), b = options.number("B", 0), c = options.number("C", 0),
               d = options.number("D", -0.01);
  if (a == 0 && b == 0 && c == 0) fail("CutPlane", "A = B = C = 0 is no plane");
  cutByGeometry(options, context, "CutPlane",
                [=](Vec3 p) { return a * p.x + b * p.y + c * p.z + d; });
}

void cutSphere(const PluginOptions& options, PluginContext& context) {
  const Vec3 center{options.number("Xc", 0), options.number("Yc", 0), options.number("Zc", 0)};
  const double r = options.number("R", 0.25);
  cutByGeometry(options, context, "CutSphere",
                [=](Vec3 p) { return dot(p - center, p - center) - r * r; });
}

void isosurface(const PluginOptions& options, PluginContext& context) {
  constexpr std::string_view plugin = "Isosurface";
  rejectExtractVolume(options, plugin);
  const double value = options.number("Value", 0);
  const std::size_t index = viewIndex(options, context, plugin);
  const View& view = context.views.at(index);
  const View& other = options.number("OtherView", -1) < 0
                          ? view
                          : context.views.at(viewIndex(options, context, plugin, "OtherView"));
  const int otherStep = int(options.number("OtherTimeStep", -1));
  if (otherStep >= std::max(other.stepCount(), 1))
    fail(plugin, optionText("OtherTimeStep", otherStep) + ": no such step in OtherView");
  for (int step = 0; step < std::max(view.stepCount(), 1); ++step) {
    View result;
    const LevelFunction level = [&](const ElementList& list, std::size_t e, int i) {
      return nodeScalar(list, e, std::min(step, list.steps - 1), i) - value;
    };
    for (const ElementList& list : view.lists) {
      if (list.size() == 0) continue;
      const ElementList& values = listLike(other, list);
      const int s = otherStep >= 0 ? otherStep : std::min(step, values.steps - 1);
      cutList(list, level, {&values, s, 1}, result);
    }
    View& added = context.views.add(view.name + "_Levelset_" + std::to_string(step));
    added.lists = std::move(result.lists);
  }
}

}  // namespace geomesh::post::plugins
