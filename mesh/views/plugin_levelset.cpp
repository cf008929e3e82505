// Plugins CutPlane, CutSphere and Isosurface: a view cut where a level function is zero,
// element by element split into simplices (tetrahedra give triangles or quadrangles,
// triangles give lines, lines give points), values interpolated linearly on the cut; or, with
// ExtractVolume, the part of the elements on one side of the cut, as simplices of their own
// dimension (elements wholly on that side are kept as they are).
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "stdlib/clamped_integer.h"
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

// Appends the element of shape `shape` whose nodes are the points `cut` of element e.
void appendCut(const std::vector<EdgePoint>& cut, ElementShape shape, const ElementList& list,
               std::size_t e, const ValueSource& source, View& result) {
  const ElementList& values = *source.list;
  ElementList& out = result.list(shape, values.kind, 1);
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
      if (!cut.empty() && removeRepeats(cut, list, e))
        appendCut(cut, cutShape(shapeDimension(list.shape), cut.size()), list, e, source, result);
    }
  }
}

// --- ExtractVolume: the part of the elements where the level (times the side) is positive.

using Piece = std::vector<EdgePoint>;

EdgePoint cornerPoint(int corner) {
  return {corner, corner, 0};
}

// The three tetrahedra of a prism whose bottom p and top q are joined edge by edge.
std::vector<Piece> splitPrism(const Piece& p, const Piece& q) {
  return {{p[0], p[1], p[2], q[0]}, {p[1], p[2], q[0], q[1]}, {p[2], q[0], q[1], q[2]}};
}

// The part of a simplex (corners `s`) where `levels` is positive, as simplices of its dimension;
// `inside` holds the corners of positive level, `outside` the others (both non-empty).
std::vector<Piece> clipSimplex(const std::vector<int>& inside, const std::vector<int>& outside,
                               const std::vector<double>& levels) {
  const auto cut = [&](int a, int b) { return crossing(a, b, levels); };
  const std::size_t corners = inside.size() + outside.size();
  const int a = inside[0];
  if (inside.size() == 1) {
    Piece piece{cornerPoint(a)};
    for (int o : outside) piece.push_back(cut(a, o));
    return {piece};
  }
  if (corners == 3) {  // a triangle with two corners kept: a quadrangle, two triangles
    const int b = inside[1], o = outside[0];
    return {{cornerPoint(a), cornerPoint(b), cut(b, o)}, {cornerPoint(a), cut(b, o), cut(a, o)}};
  }
  if (inside.size() == 3) {  // a tetrahedron less a corner: a prism
    const int b = inside[1], c = inside[2], o = outside[0];
    return splitPrism({cornerPoint(a), cornerPoint(b), cornerPoint(c)},
                      {cut(a, o), cut(b, o), cut(c, o)});
  }
  const int b = inside[1], o0 = outside[0], o1 = outside[1];  // two and two: a wedge
  return splitPrism({cornerPoint(a), cut(a, o0), cut(a, o1)},
                    {cornerPoint(b), cut(b, o0), cut(b, o1)});
}

Vec3 pointOf(const EdgePoint& p, const ElementList& list, std::size_t e) {
  const Vec3 a = elementNode(list, e, p.a), b = elementNode(list, e, p.b);
  return a + p.t * (b - a);
}

// A vector whose sign says which way a simplex of points turns: its volume, its normal or its
// direction, for 4, 3 or 2 points.
Vec3 orientation(const std::vector<Vec3>& p) {
  if (p.size() == 4) return {dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0])), 0, 0};
  if (p.size() == 3) return cross(p[1] - p[0], p[2] - p[0]);
  return p[1] - p[0];
}

// Turns a piece as its parent simplex turns (tetrahedra stay positive if the parent is).
void orientLike(Piece& piece, const std::vector<int>& parent, const ElementList& list,
                std::size_t e) {
  std::vector<Vec3> mine, theirs;
  for (const EdgePoint& p : piece) mine.push_back(pointOf(p, list, e));
  for (int corner : parent) theirs.push_back(elementNode(list, e, corner));
  if (dot(orientation(mine), orientation(theirs)) < 0) std::swap(piece[0], piece[1]);
}

bool hasRepeats(const Piece& piece, const ElementList& list, std::size_t e) {
  for (std::size_t i = 0; i < piece.size(); ++i)
    for (std::size_t j = i + 1; j < piece.size(); ++j)
      if (sameNode(piece[i], piece[j], list, e)) return true;
  return false;
}

ElementShape simplexShape(std::size_t corners) {
  return corners == 4   ? ElementShape::Tetrahedron
         : corners == 3 ? ElementShape::Triangle
                        : ElementShape::Line;
}

// Copies element e whole, with its values from the source.
void appendWhole(const ElementList& list, std::size_t e, const ValueSource& source, View& result) {
  const ElementList& values = *source.list;
  ElementList& out = result.list(list.shape, values.kind, list.order);
  out.nodesPerElement = list.nodesPerElement;
  out.steps = source.stepCount;
  std::vector<Vec3> nodes;
  for (int i = 0; i < list.nodesPerElement; ++i) nodes.push_back(elementNode(list, e, i));
  std::vector<double> data;
  for (int s = source.firstStep; s < source.firstStep + source.stepCount; ++s)
    for (int i = 0; i < list.nodesPerElement; ++i)
      for (int c = 0; c < values.components(); ++c) data.push_back(values.value(e, s, i, c));
  appendElement(out, nodes, data);
}

// Keeps the part of every element of `list` where side * level >= 0: whole elements when
// no corner is on the other side, else the clipped simplices of their split.
void extractList(const ElementList& list, const LevelFunction& level, int side,
                 const ValueSource& source, View& result) {
  const std::vector<std::vector<int>> parts = simplexSplit(list.shape);
  const int corners = cornerCount(list.shape);
  std::vector<double> levels(static_cast<std::size_t>(corners));
  for (std::size_t e = 0; e < list.size(); ++e) {
    for (int i = 0; i < corners; ++i) levels[std::size_t(i)] = side * level(list, e, i);
    if (std::all_of(levels.begin(), levels.end(), [](double l) { return l >= 0; })) {
      appendWhole(list, e, source, result);
      continue;
    }
    for (const std::vector<int>& part : parts) {
      std::vector<int> inside, outside;
      for (int corner : part)
        (levels[std::size_t(corner)] > 0 ? inside : outside).push_back(corner);
      if (inside.empty()) continue;
      for (Piece& piece : clipSimplex(inside, outside, levels)) {
        if (hasRepeats(piece, list, e)) continue;
        orientLike(piece, part, list, e);
        appendCut(piece, simplexShape(piece.size()), list, e, source, result);
      }
    }
  }
}

// The side ExtractVolume keeps: 1 (positive level), -1 (negative) or 0 (cut only).
int extractSide(const PluginOptions& options) {
  const double extract = options.number("ExtractVolume", 0);
  return extract > 0 ? 1 : extract < 0 ? -1 : 0;
}

// Cuts (side 0) or clips (side 1 or -1) the elements of `list`.
void levelsetList(const ElementList& list, const LevelFunction& level, int side,
                  const ValueSource& source, View& result) {
  if (side == 0)
    cutList(list, level, source, result);
  else
    extractList(list, level, side, source, result);
}

// Cuts the whole view (all steps) by a geometric level function: CutPlane, CutSphere.
void cutByGeometry(const PluginOptions& options, PluginContext& context, std::string_view plugin,
                   const std::function<double(Vec3)>& level) {
  const int side = extractSide(options);
  const std::size_t index = viewIndex(options, context, plugin);
  const View& view = context.views.at(index);
  View result;
  const LevelFunction nodeLevel = [&](const ElementList& list, std::size_t e, int i) {
    return level(elementNode(list, e, i));
  };
  for (const ElementList& list : view.lists)
    if (list.size() > 0) levelsetList(list, nodeLevel, side, {&list, 0, list.steps}, result);
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
  const int side = extractSide(options);
  const double value = options.number("Value", 0);
  const std::size_t index = viewIndex(options, context, plugin);
  const View& view = context.views.at(index);
  const View& other = options.number("OtherView", -1) < 0
                          ? view
                          : context.views.at(viewIndex(options, context, plugin, "OtherView"));
  const int otherStep = clampedInteger<int>(options.number("OtherTimeStep", -1));
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
      levelsetList(list, level, side, {&values, s, 1}, result);
    }
    View& added = context.views.add(view.name + "_Levelset_" + std::to_string(step));
    added.lists = std::move(result.lists);
  }
}

}  // namespace geomesh::post::plugins
