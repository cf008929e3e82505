// Building models from Python: module-level functions over one current session, named and
// ordered as the reference's Python API names them (geomesh.model.mesh.generate, ...). Each
// call is one call on the session's mesh constraints, mesher, options or writers, as the
// interpreter's statements make them; the geometry kernels' calls are in model_geometry.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "api/meshing.h"
#include "api/output.h"
#include "grammar/diagnostic.h"
#include "interpreter/run_script.h"
#include "kernel/geometry_factory.h"
#include "mesh/core/mesh_error.h"
#include "python/api_state.h"
#include "python/bindings.h"

namespace py = pybind11;

namespace geomesh::python {
namespace {

py::object moduleAttribute(const char* name) {
  return py::module_::import("geomesh._geomesh").attr(name);
}

}  // namespace

LiveSession::LiveSession() : log(err, 5), session(log, out) {
  // The OpenCASCADE-first factory SetFactory("OpenCASCADE") selects; the built-in one stays
  // selected, as in a script that never calls SetFactory.
  session.factories().select("OpenCASCADE");
  occ = &session.factories().current();
  session.factories().select("Built-in");
}

void ApiState::meshWillChange() {
  if (!current_ || current_.use_count() == 1) {
    if (current_) current_->retired.clear();
    return;
  }
  Mesh& mesh = current_->session.mesh();
  auto kept = std::make_unique<Mesh>(std::move(mesh));
  mesh = *kept;
  current_->retired.push_back(std::move(kept));
}

void raiseError(const char* type, const std::string& message) {
  PyErr_SetString(moduleAttribute(type).ptr(), message.c_str());
  throw py::error_already_set();
}

std::vector<EntityId> entityIds(const DimTags& dimTags) {
  std::vector<EntityId> ids;
  ids.reserve(dimTags.size());
  for (const auto& [dim, tag] : dimTags) ids.push_back({dim, tag});
  return ids;
}

py::list dimTagList(const std::vector<EntityId>& ids) {
  py::list list;
  for (const EntityId& id : ids) list.append(py::make_tuple(id.dim, id.tag));
  return list;
}

void warnUnsupported(const State& state, const std::string& call, const std::string& why) {
  LiveSession& s = state->live();
  if (s.firstWarning(call)) s.log.warning(call + ": " + why);
}

void synchronize(Session& session) {
  try {
    session.synchronize();
  } catch (const GeometryError&) {
    throw;
  } catch (const std::runtime_error& e) {
    raiseError("Error", e.what());
  }
}

namespace {

// ---- geomesh.model and geomesh.model.mesh ----

void defineModel(py::module_& model, const State& state) {
  model.def(
      "add", [state](const std::string& name) { state->live().modelName = name; },
      py::arg("name"), "Names the current model.");
  model.def(
      "getCurrent", [state] { return state->live().modelName; },
      "The name model.add gave the current model.");
  model.def(
      "getEntities",
      [state](int dim) {
        if (dim < -1 || dim > 3)
          throw py::value_error("dim must be -1 (all), 0, 1, 2 or 3, got " + std::to_string(dim));
        std::vector<EntityId> ids = state->session().model().entities(dim);
        for (EntityId id : partitionEntityIds(state->session(), dim)) ids.push_back(id);
        return dimTagList(ids);
      },
      py::arg("dim") = -1,
      "The model's entities [(dim, tag)] (all dimensions: dim = -1), then the partition "
      "entities of a partitioned mesh.");
  model.def(
      "addPhysicalGroup",
      [state](int dim, const std::vector<int>& tags, int tag, const std::string& name) {
        if (dim < 0 || dim > 3)
          throw py::value_error("dim must be 0, 1, 2 or 3, got " + std::to_string(dim));
        Session& session = state->session();
        GeometryFactory& groups = session.factories().builtIn();
        if (tag < 0) {
          tag = 0;
          for (const auto& [id, group] : groups.physicalGroups()) tag = std::max(tag, id.tag);
          ++tag;
        }
        // The factory keeps the group across synchronizations; the model has it at once.
        groups.addPhysicalGroup(dim, tag, name, tags);
        session.model().addPhysicalGroup(groups.physicalGroups().at({dim, tag}));
        return tag;
      },
      py::arg("dim"), py::arg("tags"), py::arg("tag") = -1, py::arg("name") = "",
      "A physical group of entities of dimension dim; returns its tag.");
}

// Elements numbered 1.. over the whole mesh, entity after entity in (dim, tag) order.
py::tuple elementsOf(const Mesh& mesh, int dim, int tag) {
  std::map<int, std::vector<std::int64_t>> elementTags, nodeTags;
  std::int64_t next = 1;
  for (const auto& [id, entity] : mesh.entities())
    for (const ElementBlock& block : entity.blocks) {
      const auto count = static_cast<std::int64_t>(block.size());
      if ((dim < 0 || id.dim == dim) && (tag < 0 || id.tag == tag)) {
        const int code = static_cast<int>(block.type);
        std::vector<std::int64_t>& tags = elementTags[code];
        for (std::int64_t k = 0; k < count; ++k) tags.push_back(next + k);
        std::vector<std::int64_t>& nodes = nodeTags[code];
        for (NodeIndex n : block.nodes) nodes.push_back(std::int64_t{n} + 1);
      }
      next += count;
    }
  py::list types, elements, nodes;
  for (const auto& [code, tags] : elementTags) {
    types.append(code);
    elements.append(py::array_t<std::int64_t>(static_cast<py::ssize_t>(tags.size()), tags.data()));
    const std::vector<std::int64_t>& n = nodeTags.at(code);
    nodes.append(py::array_t<std::int64_t>(static_cast<py::ssize_t>(n.size()), n.data()));
  }
  return py::make_tuple(types, elements, nodes);
}

// Nodes of the whole mesh (dim < 0), or those classified on one entity (with includeBoundary,
// also those of its boundary that its elements use).
py::tuple nodesOf(const Mesh& mesh, int dim, int tag, bool includeBoundary, bool parametric) {
  std::vector<std::int64_t> tags;
  std::vector<double> coords, params;
  auto add = [&](NodeIndex n) {
    tags.push_back(std::int64_t{n} + 1);
    const Vec3 p = mesh.node(n);
    coords.insert(coords.end(), {p.x, p.y, p.z});
  };
  if (dim < 0) {
    for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) add(n);
  } else if (const EntityMesh* entity = mesh.find({dim, tag})) {
    for (NodeIndex n : entity->nodes) add(n);
    if (parametric && !includeBoundary) params = entity->parametric;
    if (includeBoundary) {
      std::vector<NodeIndex> seen(entity->nodes);
      std::sort(seen.begin(), seen.end());
      for (const ElementBlock& block : entity->blocks)
        for (NodeIndex n : block.nodes)
          if (!std::binary_search(seen.begin(), seen.end(), n)) {
            seen.insert(std::upper_bound(seen.begin(), seen.end(), n), n);
            add(n);
          }
    }
  }
  auto array = [](const auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
  };
  return py::make_tuple(array(tags), array(coords), array(params));
}

void defineMeshing(py::module_& mesh, const State& state) {
  mesh.def(
      "generate",
      [state](int dim) {
        if (dim < 0 || dim > 3)
          throw py::value_error("dim must be 0, 1, 2 or 3, got " + std::to_string(dim));
        state->meshWillChange();
        Session& session = state->session();
        try {
          py::gil_scoped_release release;
          api::generate(session, dim);
        } catch (const GeometryError&) {
          throw;
        } catch (const std::runtime_error& e) {  // MeshError, ScriptError, ...
          raiseError("MeshError", e.what());
        }
      },
      py::arg("dim") = 3, "Meshes the model up to dimension dim.");
  mesh.def(
      "setSize",
      [state](const DimTags& dimTags, double size) {
        LiveSession& s = state->live();
        for (const auto& [dim, tag] : dimTags)
          if (dim == 0) s.factoryOf({0, tag}).setMeshSize({tag}, size);
      },
      py::arg("dimTags"), py::arg("size"), "The mesh size at the points among dimTags.");
  mesh.def(
      "getNodes",
      [state](int dim, int tag, bool includeBoundary, bool returnParametricCoord) {
        return nodesOf(state->session().mesh(), dim, tag, includeBoundary, returnParametricCoord);
      },
      py::arg("dim") = -1, py::arg("tag") = -1, py::arg("includeBoundary") = false,
      py::arg("returnParametricCoord") = true,
      "(nodeTags, coord, parametricCoord): int64 tags from 1, coordinates flat (3N,), and the "
      "parametric coordinates of the nodes of one curve or surface (empty otherwise).");
  mesh.def(
      "getElements",
      [state](int dim, int tag) { return elementsOf(state->session().mesh(), dim, tag); },
      py::arg("dim") = -1, py::arg("tag") = -1,
      "(elementTypes, elementTags, nodeTags): MSH type codes, and per type the int64 element "
      "tags and their node tags (from 1) flattened.");
}

// ---- geomesh.option ----

void defineOptions(py::module_& option, const State& state) {
  option.def(
      "setNumber",
      [state](const std::string& name, double value) {
        LiveSession& s = state->live();
        try {
          s.session.options().setNumber(name, value);
        } catch (const std::out_of_range&) {
          raiseError("Error", "unknown number option '" + name + "'");
        }
        if (name == "General.Verbosity") s.log.setVerbosity(static_cast<int>(value));
      },
      py::arg("name"), py::arg("value"));
  option.def(
      "getNumber",
      [state](const std::string& name) {
        try {
          return state->session().options().number(name);
        } catch (const std::out_of_range&) {
          raiseError("Error", "unknown number option '" + name + "'");
        }
      },
      py::arg("name"));
  option.def(
      "setString",
      [state](const std::string& name, const std::string& value) {
        try {
          state->session().options().setString(name, value);
        } catch (const std::out_of_range&) {
          raiseError("Error", "unknown string option '" + name + "'");
        }
      },
      py::arg("name"), py::arg("value"));
  option.def(
      "getString",
      [state](const std::string& name) {
        try {
          return state->session().options().string(name);
        } catch (const std::out_of_range&) {
          raiseError("Error", "unknown string option '" + name + "'");
        }
      },
      py::arg("name"));
}

// ---- geomesh.initialize, write, merge, ... ----

void writeFile(Session& session, const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  try {
    py::gil_scoped_release release;
    if (ext == ".geo_unrolled") return api::writeUnrolledGeometry(session, path);
    if (ext == ".opt") return api::writeChangedOptions(session, path);
    const MeshFormat& format = api::outputFormat(session.options(), path);
    // Nothing meshed yet: the file still lists the entities, as a script's Save does.
    if (session.mesh().nodeCount() == 0) session.synchronize();
    api::writeMesh(session, path, format);
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::runtime_error& e) {
    raiseError("Error", e.what());
  }
}

// Merge "path"; in the session, as a script states it.
void mergeFile(Session& session, const std::filesystem::path& path) {
  std::string quoted;
  for (char c : std::filesystem::absolute(path).string()) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  try {
    runScriptText(session, "Merge \"" + quoted + "\";\n",
                  (std::filesystem::current_path() / "<merge>").string());
  } catch (const ScriptError& e) {
    raiseError("Error", e.message());
  }
}

void defineTopLevel(py::module_& m, const State& state) {
  m.def(
      "initialize",
      [state](const std::vector<std::string>& argv, bool, bool run, bool) {
        LiveSession& s = state->live();
        // Command-line words: -v n sets the verbosity; the others (such as -nopopup) are
        // accepted and left alone.
        for (std::size_t i = 1; i + 1 < argv.size(); ++i)
          if (argv[i] == "-v") {
            const double verbosity = std::atof(argv[i + 1].c_str());
            s.session.options().setNumber("General.Verbosity", verbosity);
            s.log.setVerbosity(static_cast<int>(verbosity));
          }
        if (run)
          warnUnsupported(state, "initialize(run=True)", "files on the command line are not run");
      },
      py::arg("argv") = std::vector<std::string>{}, py::arg("readConfigFiles") = true,
      py::arg("run") = false, py::arg("interruptible") = true,
      "Starts the session the API acts on (every call starts it when needed). argv: command "
      "line words, of which -v n is read.");
  m.def(
      "isInitialized", [state] { return state->initialized(); },
      "Whether a session is started.");
  m.def(
      "finalize", [state] { state->finalize(); },
      "Ends the session: the next call starts an empty one. Mesh objects keep theirs.");
  m.def(
      "clear",
      [state] {
        state->meshWillChange();
        LiveSession& s = state->live();
        s.session.clearModel();
        s.modelName.clear();
      },
      "Empties the model (geometry, constraints, mesh); the options stay.");
  m.def(
      "write",
      [state](const std::filesystem::path& path) { writeFile(state->session(), path.string()); },
      py::arg("path"),
      "Writes the mesh in the format the file name says (.msh, .vtk, ...), or the geometry as a "
      "script (.geo_unrolled), or the changed options (.opt).");
  m.def(
      "merge",
      [state](const std::filesystem::path& path) {
        state->meshWillChange();
        mergeFile(state->session(), path);
      },
      py::arg("path"), "Reads a file into the session as a script's Merge does.");
  m.def(
      "current_mesh",
      [state] {
        std::shared_ptr<LiveSession> live = state->shared();
        Session& session = live->session;
        return std::make_unique<MeshResult>(std::move(live), session);
      },
      "The Mesh of the current session: its arrays view the mesh as it is now (a later "
      "generate leaves them as they were).");
}

void translateErrors(std::exception_ptr error) {
  try {
    if (error) std::rethrow_exception(error);
  } catch (const MeshError& e) {
    PyErr_SetString(moduleAttribute("MeshError").ptr(), e.what());
  } catch (const GeometryError& e) {
    PyErr_SetString(moduleAttribute("Error").ptr(), e.what());
  }
}

}  // namespace

void defineModelApi(py::module_& m) {
  py::register_local_exception_translator(&translateErrors);
  auto state = std::make_shared<ApiState>();
  defineTopLevel(m, state);
  py::module_ model = m.def_submodule("model", "The current model: entities, groups, mesh.");
  defineModel(model, state);
  py::module_ geo = model.def_submodule("geo", "Geometry of the built-in kernel.");
  defineGeo(geo, state);
  defineGeoOperations(geo, state);
  py::module_ occ = model.def_submodule("occ", "Geometry of the OpenCASCADE kernel.");
  defineOcc(occ, state);
  defineOccOperations(occ, state);
  py::module_ mesh = model.def_submodule("mesh", "Meshing the model and reading its mesh.");
  defineMeshing(mesh, state);
  defineMeshConstraints(mesh, state);
  defineModelQueries(model, state);
  definePartitions(model, mesh, state);
  // Calls both namespaces have: the same function under either name.
  geo.attr("addPhysicalGroup") = model.attr("addPhysicalGroup");
  py::module_ geoMesh = geo.attr("mesh");
  for (const char* name : {"setTransfiniteCurve", "setTransfiniteSurface", "setRecombine"})
    mesh.attr(name) = geoMesh.attr(name);
  py::module_ option = m.def_submodule("option", "The options of the session.");
  defineOptions(option, state);
  defineFrontEnds(m, option, state);
  py::module_ view = m.def_submodule("view", "The post-processing views of the session.");
  defineViews(view, state);
  py::module_ plugin = m.def_submodule("plugin", "The plugins that make and change views.");
  definePlugins(plugin, state);
}

}  // namespace geomesh::python
