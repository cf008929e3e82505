// Plugins MathEval and ModifyComponents: formulas of x, y, z, a view's components (v0..v8),
// another view's (w0..w8), Time and TimeStep, evaluated at every node of a view.
#include <array>
#include <map>
#include <exception>
#include <string>
#include <vector>

#include "stdlib/clamped_integer.h"
#include "mesh/views/plugin_functions.h"

namespace geomesh::post::plugins {
namespace {

// The variables formulas may use, in the order their values are passed.
constexpr int kVariableCount = 23;
constexpr int kV = 3, kW = 12, kTime = 21, kTimeStep = 22;
using Variables = std::array<double, kVariableCount>;

std::vector<std::string> variableNames() {
  std::vector<std::string> names = {"x", "y", "z"};
  for (const char letter : {'v', 'w'})
    for (int i = 0; i < 9; ++i) names.push_back(std::string(1, letter) + std::to_string(i));
  names.push_back("Time");
  names.push_back("TimeStep");
  return names;
}

// Expression0..8 compiled; an empty expression stays an empty function.
std::vector<CompiledFormula> compileExpressions(const PluginOptions& options,
                                                const PluginContext& context,
                                                std::string_view plugin,
                                                const std::string& firstDefault) {
  if (!context.compileFormula) fail(plugin, "no formula evaluator in this session");
  const std::vector<std::string> names = variableNames();
  std::vector<CompiledFormula> formulas(9);
  for (int i = 0; i < 9; ++i) {
    const std::string option = "Expression" + std::to_string(i);
    const std::string text = options.text(option, i == 0 ? firstDefault : "");
    if (text.empty()) continue;
    try {
      formulas[std::size_t(i)] = context.compileFormula(text, names);
    } catch (const std::exception& error) {
      fail(plugin, option + " = \"" + text + "\": " + error.what());
    }
  }
  return formulas;
}

// The list of `other` laid out as `list` (same shape, order and element count), for w0..w8.
const ElementList* matchingList(const View& other, const ElementList& list,
                                std::string_view plugin) {
  for (const ElementList& candidate : other.lists)
    if (candidate.shape == list.shape && candidate.order == list.order &&
        candidate.size() == list.size() && candidate.nodesPerElement == list.nodesPerElement)
      return &candidate;
  fail(plugin, "OtherView \"" + other.name + "\" has no " + shapeLetter(list.shape) +
                   " elements laid out as View's (interpolation between views is not supported)");
}

double stepTime(const View& view, int step) {
  return std::size_t(step) < view.times.size() ? view.times[std::size_t(step)] : double(step);
}

// Where the values of a node come from: the view's list at a step, the other view's at its.
struct NodeSource {
  const ElementList& list;
  int step;
  const ElementList* other;
  int otherStep;
  double time;
};

void setVariables(Variables& vars, const NodeSource& source, std::size_t e, int node) {
  const Vec3 p = elementNode(source.list, e, node);
  vars.fill(0);
  vars[0] = p.x, vars[1] = p.y, vars[2] = p.z;
  for (int c = 0; c < source.list.components(); ++c)
    vars[std::size_t(kV + c)] = source.list.value(e, source.step, node, c);
  if (source.other)
    for (int c = 0; c < source.other->components(); ++c)
      vars[std::size_t(kW + c)] = source.other->value(e, source.otherStep, node, c);
  vars[kTime] = source.time;
  vars[kTimeStep] = source.step;
}

int otherStepFor(const ElementList* other, int requested, int step) {
  if (!other) return 0;
  const int wanted = requested < 0 ? step : requested;
  return wanted < other->steps ? wanted : 0;
}

FieldKind kindOfCount(int count) {
  return count == 1 ? FieldKind::Scalar : count <= 3 ? FieldKind::Vector : FieldKind::Tensor;
}

struct EvalSetup {
  const View& view;
  const View& other;
  bool useOther;
  int step;       // -1: all
  int otherStep;  // -1: the current step
};

// MathEval on one list: a new list of `kind` with the same elements.
void evaluateList(const EvalSetup& setup, const ElementList& list,
                  const std::vector<CompiledFormula>& formulas, FieldKind kind, View& result,
                  std::string_view plugin) {
  const ElementList* other = setup.useOther ? matchingList(setup.other, list, plugin) : nullptr;
  ElementList& out = result.list(list.shape, kind, list.order);
  out.nodesPerElement = list.nodesPerElement;
  const int first = setup.step < 0 ? 0 : setup.step;
  const int last = setup.step < 0 ? list.steps - 1 : setup.step;
  out.steps = last - first + 1;
  out.coordinates.insert(out.coordinates.end(), list.coordinates.begin(), list.coordinates.end());
  const int components = componentCount(kind);
  Variables vars{};
  for (std::size_t e = 0; e < list.size(); ++e)
    for (int s = first; s <= last; ++s) {
      const NodeSource source{list, s, other, otherStepFor(other, setup.otherStep, s),
                              stepTime(setup.view, s)};
      for (int n = 0; n < list.nodesPerElement; ++n) {
        setVariables(vars, source, e, n);
        for (int c = 0; c < components; ++c)
          out.values.push_back(formulas[std::size_t(c)] ? formulas[std::size_t(c)](vars) : 0.0);
      }
    }
}

// ModifyComponents on one list, in place: only the components whose expression is given.
void modifyList(const EvalSetup& setup, ElementList& list,
                const std::vector<CompiledFormula>& formulas, std::string_view plugin) {
  const ElementList* other = setup.useOther ? matchingList(setup.other, list, plugin) : nullptr;
  const ElementList before = list;  // formulas read the values as they were
  const int first = setup.step < 0 ? 0 : setup.step;
  const int last = setup.step < 0 ? list.steps - 1 : std::min(setup.step, list.steps - 1);
  const int components = list.components();
  const ElementList* otherSource = other == &list ? &before : other;
  Variables vars{};
  for (std::size_t e = 0; e < list.size(); ++e)
    for (int s = first; s <= last; ++s) {
      const NodeSource source{before, s, otherSource, otherStepFor(otherSource, setup.otherStep, s),
                              stepTime(setup.view, s)};
      for (int n = 0; n < list.nodesPerElement; ++n) {
        setVariables(vars, source, e, n);
        for (int c = 0; c < components; ++c)
          if (formulas[std::size_t(c)])
            list.values[e * list.valuesPerElement() +
                        (std::size_t(s) * std::size_t(list.nodesPerElement) + std::size_t(n)) *
                            std::size_t(components) +
                        std::size_t(c)] = formulas[std::size_t(c)](vars);
      }
    }
}

int lastGiven(const std::vector<CompiledFormula>& formulas) {
  int last = -1;
  for (int i = 0; i < 9; ++i)
    if (formulas[std::size_t(i)]) last = i;
  return last;
}

// The other view (OtherView; itself when negative) and whether formulas may read it.
const View& otherView(const PluginOptions& options, const PluginContext& context, const View& view,
                      std::string_view plugin) {
  if (options.number("OtherView", -1) < 0) return view;
  return context.views.at(viewIndex(options, context, plugin, "OtherView"));
}

}  // namespace

void mathEval(const PluginOptions& options, PluginContext& context) {
  constexpr std::string_view plugin = "MathEval";
  const std::vector<CompiledFormula> formulas =
      compileExpressions(options, context, plugin, "Sqrt(v0^2+v1^2+v2^2)");
  const int last = lastGiven(formulas);
  if (last < 0) fail(plugin, "every expression is empty");
  if (options.number("PhysicalRegion", -1) >= 0)
    context.log.warning("Plugin(MathEval): PhysicalRegion is ignored on list-based views");
  const std::size_t index = viewIndex(options, context, plugin);
  const View& view = context.views.at(index);
  const View& other = otherView(options, context, view, plugin);
  const EvalSetup setup{view, other, true, stepOption(options, view, plugin, "TimeStep", -1, true),
                        clampedInteger<int>(options.number("OtherTimeStep", -1))};
  View result;
  for (const ElementList& list : view.lists)
    if (list.size() > 0) evaluateList(setup, list, formulas, kindOfCount(last + 1), result, plugin);
  View& added = context.views.add(view.name + "_MathEval");
  added.lists = std::move(result.lists);
  if (setup.step < 0) added.times = context.views.at(index).times;
}

namespace {

// After the element lists changed in place, the data kept as a mesh file gave it must follow:
// node data take the new values at their nodes (found by their coordinates, nodes numbered
// as the mesh's, from 1); other kinds are dropped, the view then written from its lists.
void refreshMeshData(View& view, const Mesh& mesh) {
  if (!view.meshData) return;
  MeshData& data = *view.meshData;
  if (data.kind != MeshData::Kind::Node) {
    view.meshData.reset();
    return;
  }
  std::map<std::array<double, 3>, std::size_t> nodeAt;  // coordinates -> tag
  for (const MeshData::Step& step : data.steps)
    for (std::size_t tag : step.tags)
      if (tag >= 1 && tag <= mesh.nodeCount()) {
        const Vec3 p = mesh.node(static_cast<NodeIndex>(tag - 1));
        nodeAt.emplace(std::array<double, 3>{p.x, p.y, p.z}, tag);
      }
  for (std::size_t s = 0; s < data.steps.size(); ++s) {
    MeshData::Step& step = data.steps[s];
    const int stepOfList = static_cast<int>(s);  // the lists hold the steps in this order
    std::map<std::size_t, std::size_t> slot;  // tag -> position in the step
    for (std::size_t k = 0; k < step.tags.size(); ++k) slot.emplace(step.tags[k], k);
    const auto c = std::size_t(data.components);
    for (const ElementList& list : view.lists) {
      if (list.components() != data.components || stepOfList >= list.steps) continue;
      for (std::size_t e = 0; e < list.size(); ++e)
        for (int i = 0; i < list.nodesPerElement; ++i) {
          const double* xyz = &list.coordinates[3 * (e * std::size_t(list.nodesPerElement) + std::size_t(i))];
          const auto tag = nodeAt.find({xyz[0], xyz[1], xyz[2]});
          if (tag == nodeAt.end()) continue;
          const auto at = slot.find(tag->second);
          if (at == slot.end()) continue;
          for (std::size_t j = 0; j < c; ++j)
            step.values[at->second * c + j] = list.value(e, stepOfList, i, int(j));
        }
    }
  }
}

}  // namespace

void modifyComponents(const PluginOptions& options, PluginContext& context) {
  constexpr std::string_view plugin = "ModifyComponents";
  const std::vector<CompiledFormula> formulas =
      compileExpressions(options, context, plugin, "v0 * Sin(x)");
  View& view = context.views.at(viewIndex(options, context, plugin));
  const View& other = otherView(options, context, view, plugin);
  const EvalSetup setup{view, other, true, stepOption(options, view, plugin, "TimeStep", -1, true),
                        clampedInteger<int>(options.number("OtherTimeStep", -1))};
  for (ElementList& list : view.lists)
    if (list.size() > 0) modifyList(setup, list, formulas, plugin);
  refreshMeshData(view, context.mesh);
}

}  // namespace geomesh::post::plugins
