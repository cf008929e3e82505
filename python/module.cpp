// The compiled part of `import geomesh`: run a .geo script as the geomesh command does and
// read the mesh it made as NumPy arrays; the model-building API is in python/model_api.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "api/output.h"
#include "app/mesh_summary.h"
#include "app/script_run.h"
#include "python/bindings.h"
#include "python/python_stream.h"
#include "grammar/diagnostic.h"
#include "mesh/core/mesh_error.h"
#include "stdlib/build_info.h"

namespace py = pybind11;

namespace geomesh::python {
namespace {

// The module's exception types, kept by the functions that raise them.
struct ErrorTypes {
  py::object script;
  py::object mesh;
};

py::object newErrorType(py::module_& m, const char* name, const char* doc, PyObject* base) {
  const std::string qualified = std::string("geomesh.") + name;
  auto type = py::reinterpret_steal<py::object>(
      PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr));
  if (!type) throw py::error_already_set();
  type.attr("file") = py::none();
  type.attr("line") = py::none();
  type.attr("column") = py::none();
  m.attr(name) = type;
  return type;
}

// Raises `type` with `message`, its file, line and column set when the error is located.
[[noreturn]] void raise(const py::object& type, const char* message, const SourceLocation* where) {
  py::object error = type(message);
  if (where) {
    error.attr("file") = where->file;
    error.attr("line") = where->line;
    error.attr("column") = where->column;
  }
  PyErr_SetObject(type.ptr(), error.ptr());
  throw py::error_already_set();
}

using Numbers = std::optional<std::map<std::string, double>>;
using Strings = std::optional<std::map<std::string, std::string>>;

// The command line the run stands for: `geomesh path -<dim> -setnumber ... -o output -v ...`.
CommandLine runSettings(const std::filesystem::path& path, int dim, const Numbers& numbers,
                        const Strings& strings, const std::optional<std::filesystem::path>& output,
                        int verbosity) {
  if (dim < 0 || dim > 3)
    throw py::value_error("dim must be 0, 1, 2 or 3, got " + std::to_string(dim));
  CommandLine settings;
  settings.files = {path.string()};
  settings.dimension = dim;
  settings.verbosity = verbosity;
  if (output) settings.output = output->string();
  if (numbers) settings.setNumbers.assign(numbers->begin(), numbers->end());
  if (strings) settings.setStrings.assign(strings->begin(), strings->end());
  return settings;
}

// A script run whose output goes to Python's streams: Printf to sys.stdout, log lines to
// sys.stderr.
struct PythonScriptRun {
  explicit PythonScriptRun(CommandLine settings) : run(std::move(settings), out, err) {}
  PythonStream out{"stdout"};
  PythonStream err{"stderr"};
  ScriptRun run;
};

// Evaluates, then meshes, without the GIL. A ScriptError met while meshing is a meshing
// failure located at the statement of its entity: it raises MeshError, with its location.
std::unique_ptr<MeshResult> runScript(const ErrorTypes& errors, CommandLine settings) {
  auto owned = std::make_unique<PythonScriptRun>(std::move(settings));
  ScriptRun& run = owned->run;
  bool meshing = false;
  try {
    py::gil_scoped_release release;
    if (run.evaluate()) {
      meshing = true;
      run.meshAndWrite();
    }
  } catch (const ScriptError& e) {
    raise(meshing ? errors.mesh : errors.script, e.what(), &e.location());
  } catch (const MeshError& e) {
    raise(errors.mesh, e.what(), nullptr);
  }
  // Nothing changes a finished run's mesh: the views of its arrays stay valid.
  std::shared_ptr<PythonScriptRun> owner = std::move(owned);
  Session& session = owner->run.session();
  return std::make_unique<MeshResult>(std::move(owner), session);
}

void makeReadOnly(py::array& array) { array.attr("setflags")(py::arg("write") = false); }

// The node coordinates, (N, 3), viewing the mesh's own array.
py::array nodeArray(const py::object& self) {
  const std::span<const double> xyz = self.cast<const MeshResult&>().mesh().coordinates();
  const auto rows = static_cast<py::ssize_t>(xyz.size() / 3);
  constexpr py::ssize_t kDouble = sizeof(double);
  py::array array =
      py::array_t<double>({rows, py::ssize_t{3}}, {3 * kDouble, kDouble}, xyz.data(), self);
  makeReadOnly(array);
  return array;
}

py::array nodeTags(const MeshResult& result) {
  const auto count = static_cast<py::ssize_t>(result.mesh().nodeCount());
  py::array_t<std::int64_t> tags(count);
  auto view = tags.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < count; ++i) view(i) = i + 1;
  return tags;
}

// Elements of the entities of dimension `dim` (-1: all), one (N, nodes per element) array per
// type, blocks of one type joined in the order of the entities.
py::dict elementArrays(const MeshResult& result, int dim) {
  if (dim < -1 || dim > 3)
    throw py::value_error("dim must be -1 (all), 0, 1, 2 or 3, got " + std::to_string(dim));
  std::map<ElementType, std::vector<const ElementBlock*>> byType;
  for (const auto& [id, entity] : result.mesh().entities())
    if (dim < 0 || id.dim == dim)
      for (const ElementBlock& block : entity.blocks)
        if (block.size() > 0) byType[block.type].push_back(&block);
  py::dict arrays;
  for (const auto& [type, blocks] : byType) {
    std::size_t rows = 0;
    for (const ElementBlock* block : blocks) rows += block->size();
    const auto width = static_cast<py::ssize_t>(nodeCount(type));
    py::array_t<NodeIndex> array({static_cast<py::ssize_t>(rows), width});
    NodeIndex* out = array.mutable_data();
    for (const ElementBlock* block : blocks)
      out = std::copy(block->nodes.begin(), block->nodes.end(), out);
    arrays[elementName(type)] = std::move(array);
  }
  return arrays;
}

// The elements of one entity, each type's array viewing the mesh's own connectivity.
py::dict entityElements(const py::object& self, int dim, int tag) {
  const MeshResult& result = self.cast<const MeshResult&>();
  const EntityId id{dim, tag};
  const EntityMesh* entity = result.mesh().find(id);
  if (!entity && !result.session().model().contains(id))
    throw py::value_error("no entity (" + std::to_string(dim) + ", " + std::to_string(tag) +
                          ") in the model");
  py::dict arrays;
  if (!entity) return arrays;
  for (const ElementBlock& block : entity->blocks) {
    if (block.size() == 0) continue;
    const py::ssize_t width = nodeCount(block.type);
    py::array array = py::array_t<NodeIndex>(
        {static_cast<py::ssize_t>(block.size()), width},
        {width * py::ssize_t{sizeof(NodeIndex)}, py::ssize_t{sizeof(NodeIndex)}},
        block.nodes.data(), self);
    makeReadOnly(array);
    arrays[elementName(block.type)] = std::move(array);
  }
  return arrays;
}

py::list entityList(const MeshResult& result) {
  py::list entities;
  for (const EntityId& id : result.session().model().entities(-1))
    entities.append(py::make_tuple(id.dim, id.tag));
  return entities;
}

py::list physicalGroupList(const MeshResult& result) {
  py::list groups;
  for (const auto& [id, group] : result.session().model().physicalGroups())
    groups.append(py::make_tuple(group.dim, group.tag, group.name, py::cast(group.entities)));
  return groups;
}

py::dict summaryDict(const MeshResult& result) {
  const MeshSummary summary = summarizeMesh(result.session().model(), result.mesh());
  py::dict elements;
  for (const auto& [type, count] : summary.elements) elements[elementName(type)] = count;
  py::dict d;
  d["nodes"] = summary.nodes;
  d["elements"] = elements;
  d["length"] = summary.length;
  d["area"] = summary.area;
  d["volume"] = summary.volume;
  d["quality_min"] = summary.minQuality;
  d["quality_mean"] = summary.meanQuality;
  return d;
}

void writeMesh(MeshResult& result, const std::filesystem::path& path) {
  const std::string file = path.string();
  py::gil_scoped_release release;
  api::writeMesh(result.session(), file, api::outputFormat(result.session().options(), file));
}

std::string describe(const MeshResult& result) {
  return "<geomesh.Mesh: " + std::to_string(result.mesh().nodeCount()) + " nodes, " +
         std::to_string(result.mesh().elementCount(-1)) + " elements>";
}

void defineMesh(py::module_& m) {
  py::class_<MeshResult> mesh(m, "Mesh",
                              "The model and mesh of one run; arrays view its memory.");
  mesh.attr("__module__") = "geomesh";
  mesh.def_property_readonly("nodes", &nodeArray,
                             "Node coordinates, (N, 3) float64, a read-only view of the mesh's "
                             "own array (no copy).")
      .def_property_readonly("node_tags", &nodeTags, "Node tags: 1..N, in the order of nodes.")
      .def("elements", &elementArrays, py::arg("dim") = -1,
           "{type name: (N, nodes per element) uint32 array of 0-based node indices} over the "
           "entities of dimension dim (-1: all); fresh arrays.")
      .def("elements_of", &entityElements, py::arg("dim"), py::arg("tag"),
           "The same dict for one entity, read-only views of the mesh's own arrays.")
      .def_property_readonly("entities", &entityList, "The model's entities: [(dim, tag)].")
      .def_property_readonly("physical_groups", &physicalGroupList,
                             "[(dim, tag, name, [entity tags])].")
      .def("summary", &summaryDict,
           "The run's summary: nodes, element counts per type, length, area, volume, quality.")
      .def("write", &writeMesh, py::arg("path"),
           "Writes the mesh in the format the file name says, as -o does.")
      .def("__repr__", &describe);
}

}  // namespace
}  // namespace geomesh::python

PYBIND11_MODULE(_geomesh, m) {
  using namespace geomesh::python;
  m.doc() = "geomesh: Gmsh-compatible .geo scripts meshed, models built from Python, meshes "
            "read as NumPy arrays.";
  m.attr("__version__") = GEOMESH_VERSION;
  py::object base = newErrorType(m, "Error", "Base of geomesh's errors.", PyExc_Exception);
  ErrorTypes errors;
  errors.script = newErrorType(m, "ScriptError", "A located error in a .geo script.", base.ptr());
  errors.mesh = newErrorType(m, "MeshError", "Meshing failed.", base.ptr());
  defineMesh(m);
  m.def(
      "run",
      [errors](const std::filesystem::path& path, int dim, const Numbers& numbers,
               const Strings& strings, const std::optional<std::filesystem::path>& output,
               int verbosity) {
        return runScript(errors, runSettings(path, dim, numbers, strings, output, verbosity));
      },
      py::arg("path"), py::arg("dim") = 3, py::arg("numbers") = py::none(),
      py::arg("strings") = py::none(), py::arg("output") = py::none(),
      py::arg("verbosity") = 5,
      "Runs a .geo script as `geomesh path -<dim> [-setnumber k v]... [-setstring k v]... "
      "[-o output] [-v verbosity]` does and returns its Mesh. dim 0 evaluates the geometry "
      "only.");
  defineModelApi(m);
}
