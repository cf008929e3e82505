// geomesh.view and geomesh.view.option: the session's post-processing views (mesh/views/view.h)
// made, filled, written and given options from Python, as a script's View "..." {...};,
// View[n].X = v; and Save View[n] do.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/view_file_parts.h"
#include "io/view_files.h"
#include "python/api_state.h"

namespace py = pybind11;

namespace geomesh::python {
namespace {

post::View& viewOfTag(Session& session, int tag) {
  post::View* view = session.views().withTag(tag);
  if (!view) raiseError("Error", "no view has tag " + std::to_string(tag));
  return *view;
}

// A view of a given tag replaces the view that has it; views made without one take the next
// tag the store gives, past any tag chosen here.
int addView(Session& session, const std::string& name, int tag) {
  post::ViewStore& views = session.views();
  if (tag >= 0)
    if (const int index = views.indexOfTag(tag); index >= 0) views.remove(std::size_t(index));
  post::View& view = views.add(name);
  int highest = -1;
  for (std::size_t i = 0; i + 1 < views.size(); ++i) highest = std::max(highest, views.at(i).tag);
  if (tag >= 0)
    view.tag = tag;
  else if (view.tag <= highest)
    view.tag = highest + 1;
  return view.tag;
}

// A list type of the list format ("SP", "VT", "ST2", ...), or Error.
post::ListType listType(const std::string& type) {
  const std::optional<post::ListType> list = post::listTypeOf(type);
  if (!list) raiseError("Error", "'" + type + "' is not a list data type (SP, VL, TT, ST2, ...)");
  return *list;
}

// numEle elements of one type, each its node coordinates (all x, then all y, then all z) then
// its values, step after step, node after node.
void addListData(post::View& view, const std::string& dataType, int count,
                 const std::vector<double>& data) {
  const post::ListType type = listType(dataType);
  if (count <= 0 || data.size() % std::size_t(count) != 0)
    raiseError("Error", std::to_string(data.size()) + " values are not " +
                            std::to_string(count) + " elements of the same size");
  const std::size_t nodes = std::size_t(listNodeCount(type.shape, type.order));
  const std::size_t perElement = data.size() / std::size_t(count);
  const std::size_t perStep = nodes * std::size_t(post::componentCount(type.field));
  if (perElement <= 3 * nodes || (perElement - 3 * nodes) % perStep != 0)
    raiseError("Error", dataType + " elements take " + std::to_string(3 * nodes) +
                            " coordinates and " + std::to_string(perStep) +
                            " values per time step, not " + std::to_string(perElement) +
                            " numbers");
  const int steps = static_cast<int>((perElement - 3 * nodes) / perStep);
  post::ElementList& list = view.list(type.shape, type.field, type.order);
  if (list.size() > 0 && list.steps != steps)
    raiseError("Error", dataType + " data of " + std::to_string(steps) +
                            " time steps where the view's has " + std::to_string(list.steps));
  list.nodesPerElement = static_cast<int>(nodes);
  list.steps = steps;
  for (std::size_t e = 0; e < std::size_t(count); ++e) {
    const double* element = data.data() + e * perElement;
    for (std::size_t i = 0; i < nodes; ++i)
      for (std::size_t c = 0; c < 3; ++c) list.coordinates.push_back(element[c * nodes + i]);
    list.values.insert(list.values.end(), element + 3 * nodes, element + perElement);
  }
}

// Text at window coordinates (x, y) or model coordinates (x, y, z), one string per step.
void addListDataString(const State& state, post::View& view, const std::vector<double>& coord,
                       const std::vector<std::string>& data,
                       const std::vector<std::string>& style) {
  if (coord.size() != 2 && coord.size() != 3)
    raiseError("Error", "a text is placed by 2 (x, y) or 3 (x, y, z) coordinates, not " +
                            std::to_string(coord.size()));
  post::TextItem text;
  text.dimension = static_cast<int>(coord.size());
  text.x = coord[0];
  text.y = coord[1];
  if (coord.size() == 3) text.z = coord[2];
  text.text = data;
  view.texts.push_back(std::move(text));
  if (!style.empty())
    warnUnsupported(state, "view.addListDataString(style=...)",
                    "text styles change only the display; the text is kept without them");
}

// The values of each tag, as the reference's API gives them: one list per tag, or one flat
// list of numComponents values per tag.
std::vector<double> flatValues(const py::sequence& data, std::size_t tags, int& components) {
  std::vector<double> values;
  const bool nested = py::len(data) > 0 && py::isinstance<py::sequence>(data[0]);
  if (nested) {
    if (py::len(data) != tags)
      raiseError("Error", std::to_string(py::len(data)) + " value lists for " +
                              std::to_string(tags) + " tags");
    for (const py::handle row : data) {
      const auto numbers = row.cast<std::vector<double>>();
      if (components < 0) components = static_cast<int>(numbers.size());
      if (numbers.size() != std::size_t(components))
        raiseError("Error", "every tag takes " + std::to_string(components) + " values");
      values.insert(values.end(), numbers.begin(), numbers.end());
    }
  } else {
    values = data.cast<std::vector<double>>();
    if (components < 0 && tags > 0) components = static_cast<int>(values.size() / tags);
  }
  if (components <= 0 || values.size() != tags * std::size_t(components))
    raiseError("Error", std::to_string(values.size()) + " values are not " +
                            std::to_string(tags) + " tags of the same number of components");
  return values;
}

// Data on the nodes or elements of the session's mesh for one time step: the step replaces one
// of the same number.
void addModelData(post::View& view, const Mesh& mesh, int step, const std::string& dataType,
                  const std::vector<std::size_t>& tags, const py::sequence& data, double time,
                  int components) {
  post::MeshData::Kind kind;
  if (dataType == "NodeData")
    kind = post::MeshData::Kind::Node;
  else if (dataType == "ElementData")
    kind = post::MeshData::Kind::Element;
  else
    raiseError("Error", "model data of type '" + dataType +
                            "': geomesh takes NodeData and ElementData");
  std::vector<double> values = flatValues(data, tags.size(), components);
  if (components != 1 && components != 2 && components != 3 && components != 9)
    raiseError("Error", std::to_string(components) + " components: not 1, 2, 3 or 9");
  std::size_t limit = mesh.nodeCount();
  if (kind == post::MeshData::Kind::Element) {
    limit = 0;
    for (const auto& [id, entity] : mesh.entities())
      for (const ElementBlock& block : entity.blocks) limit += block.size();
  }
  const std::string what = kind == post::MeshData::Kind::Node ? "node" : "element";
  for (const std::size_t t : tags)
    if (t < 1 || t > limit)
      raiseError("Error", "no " + what + " has tag " + std::to_string(t) + " in the mesh");
  if (view.meshData && (view.meshData->kind != kind || view.meshData->components != components))
    raiseError("Error", "view " + std::to_string(view.tag) +
                            " holds model data of another type or number of components");
  if (!view.meshData) view.meshData = post::MeshData{kind, components, {}};
  auto& steps = view.meshData->steps;
  const auto sameStep = [&](const auto& s) { return s.index == step; };
  auto it = std::find_if(steps.begin(), steps.end(), sameStep);
  if (it == steps.end()) {
    it = std::find_if(steps.begin(), steps.end(), [&](const auto& s) { return s.index > step; });
    it = steps.insert(it, post::MeshData::Step{});
  }
  *it = post::MeshData::Step{time, step, tags, {}, std::move(values)};
  view.times.clear();
  for (const auto& s : steps) view.times.push_back(s.time);
  buildMeshDataLists(view, mesh);
}

void writeView(Session& session, int tag, const std::string& path, bool append) {
  const post::View& view = viewOfTag(session, tag);
  try {
    geomesh::writeView(view, path, session.mesh(),
                       session.options().number("Mesh.MshFileVersion"), append);
  } catch (const std::runtime_error& e) {
    raiseError("Error", e.what());
  }
  session.log().info("Wrote view '" + view.name + "' to '" + path + "'");
}

void defineViewCalls(py::module_& view, const State& state) {
  view.def(
      "add",
      [state](const std::string& name, int tag) { return addView(state->session(), name, tag); },
      py::arg("name"), py::arg("tag") = -1,
      "Adds an empty view; returns its tag (the next one when tag is -1).");
  view.def(
      "remove",
      [state](int tag) {
        post::ViewStore& views = state->session().views();
        viewOfTag(state->session(), tag);
        views.remove(std::size_t(views.indexOfTag(tag)));
      },
      py::arg("tag"), "Removes the view of a tag.");
  view.def(
      "getTags",
      [state] {
        std::vector<int> tags;
        const post::ViewStore& views = state->session().views();
        for (std::size_t i = 0; i < views.size(); ++i) tags.push_back(views.at(i).tag);
        return tags;
      },
      "The tags of the views, in the order of their indices.");
  view.def(
      "getIndex",
      [state](int tag) {
        viewOfTag(state->session(), tag);
        return state->session().views().indexOfTag(tag);
      },
      py::arg("tag"), "The index of the view of a tag (View[index] in a script).");
  view.def(
      "addListData",
      [state](int tag, const std::string& dataType, int numEle, const std::vector<double>& data) {
        addListData(viewOfTag(state->session(), tag), dataType, numEle, data);
      },
      py::arg("tag"), py::arg("dataType"), py::arg("numEle"), py::arg("data"),
      "Adds numEle elements of a list type (SP, VL, ST, SS2, ...): each its node coordinates "
      "(all x, all y, all z), then its values, step after step.");
  view.def(
      "addListDataString",
      [state](int tag, const std::vector<double>& coord, const std::vector<std::string>& data,
              const std::vector<std::string>& style) {
        addListDataString(state, viewOfTag(state->session(), tag), coord, data, style);
      },
      py::arg("tag"), py::arg("coord"), py::arg("data"),
      py::arg("style") = std::vector<std::string>{},
      "Adds a text: at window coordinates [x, y] or model coordinates [x, y, z], one string "
      "per time step.");
}

void defineModelDataCalls(py::module_& view, const State& state) {
  const auto add = [state](int tag, int step, const std::string&, const std::string& dataType,
                           const std::vector<std::size_t>& tags, const py::sequence& data,
                           double time, int numComponents, int) {
    Session& session = state->session();
    addModelData(viewOfTag(session, tag), session.mesh(), step, dataType, tags, data, time,
                 numComponents);
  };
  const char* doc =
      "Adds one time step of data on the mesh's nodes (NodeData) or elements (ElementData): "
      "values for each tag, one list per tag or numComponents values per tag in one list.";
  for (const char* name : {"addModelData", "addHomogeneousModelData"})
    view.def(name, add, py::arg("tag"), py::arg("step"), py::arg("modelName"),
             py::arg("dataType"), py::arg("tags"), py::arg("data"), py::arg("time") = 0.0,
             py::arg("numComponents") = -1, py::arg("partition") = 0, doc);
  view.def(
      "write",
      [state](int tag, const std::string& fileName, bool append) {
        writeView(state->session(), tag, fileName, append);
      },
      py::arg("tag"), py::arg("fileName"), py::arg("append") = false,
      "Writes a view as Save View does: .pos (parsed format) or .msh.");
}

// View[n].X values computed from the data rather than set.
std::optional<double> computedOption(const post::View& view, const std::string& name) {
  if (name == "Max") return view.maximum();
  if (name == "Min") return view.minimum();
  if (name == "NbTimeStep") return double(view.stepCount());
  if (name == "NbElements") return double(view.elementCount());
  return std::nullopt;
}

void defineViewOptions(py::module_& option, const State& state) {
  option.def(
      "setNumber",
      [state](int tag, const std::string& name, double value) {
        viewOfTag(state->session(), tag).numbers[name] = value;
      },
      py::arg("tag"), py::arg("name"), py::arg("value"),
      "Sets a number option of a view, as View[index].name = value; does.");
  option.def(
      "getNumber",
      [state](int tag, const std::string& name) {
        const post::View& view = viewOfTag(state->session(), tag);
        if (const auto computed = computedOption(view, name)) return *computed;
        const auto it = view.numbers.find(name);
        return it == view.numbers.end() ? 0.0 : it->second;
      },
      py::arg("tag"), py::arg("name"),
      "A number option of a view: as set, or computed (Max, Min, NbTimeStep, NbElements); 0 "
      "otherwise.");
  option.def(
      "setString",
      [state](int tag, const std::string& name, const std::string& value) {
        post::View& view = viewOfTag(state->session(), tag);
        if (name == "Name")
          view.name = value;
        else
          view.strings[name] = value;
      },
      py::arg("tag"), py::arg("name"), py::arg("value"), "Sets a string option of a view.");
  option.def(
      "getString",
      [state](int tag, const std::string& name) {
        const post::View& view = viewOfTag(state->session(), tag);
        if (name == "Name") return view.name;
        const auto it = view.strings.find(name);
        return it == view.strings.end() ? std::string() : it->second;
      },
      py::arg("tag"), py::arg("name"), "A string option of a view; \"\" when not set.");
  option.def(
      "setColor",
      [state](int tag, const std::string& name, int r, int g, int b, int a) {
        viewOfTag(state->session(), tag);
        state->live().colors["View[" + std::to_string(tag) + "]." + name] = {r, g, b, a};
      },
      py::arg("tag"), py::arg("name"), py::arg("r"), py::arg("g"), py::arg("b"),
      py::arg("a") = 255, "Keeps a display color of a view (nothing is displayed).");
  option.def(
      "getColor",
      [state](int tag, const std::string& name) {
        viewOfTag(state->session(), tag);
        const auto& colors = state->live().colors;
        const auto it = colors.find("View[" + std::to_string(tag) + "]." + name);
        const std::array<int, 4> rgba =
            it == colors.end() ? std::array<int, 4>{0, 0, 0, 255} : it->second;
        return py::make_tuple(rgba[0], rgba[1], rgba[2], rgba[3]);
      },
      py::arg("tag"), py::arg("name"), "The color setColor gave; (0, 0, 0, 255) otherwise.");
}

}  // namespace

void defineViews(py::module_& view, const State& state) {
  defineViewCalls(view, state);
  defineModelDataCalls(view, state);
  py::module_ option = view.def_submodule("option", "The options of one view, by its tag.");
  defineViewOptions(option, state);
}

}  // namespace geomesh::python
