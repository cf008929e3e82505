// The model API's state: the current session, shared by the functions of python/model_api.cpp
// and python/model_geometry.cpp, and the helpers both use.
#pragma once

#include <pybind11/pybind11.h>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "api/session.h"
#include "app/console_log.h"
#include "kernel/geometry_factory.h"
#include "kernel/model.h"
#include "mesh/views/plugins.h"
#include "python/python_stream.h"

namespace geomesh::python {

using DimTags = std::vector<std::pair<int, int>>;

// The API's log: the console's, and while logger.start() is in effect, a record of the
// messages the verbosity lets through, as "Info: ..." / "Warning: ...", for logger.get().
class RecordingLog final : public MessageSink {
 public:
  RecordingLog(std::ostream& err, int verbosity)
      : console_(err, verbosity), verbosity_(verbosity) {}
  void info(std::string_view message) override {
    if (verbosity_ >= 4) record("Info: ", message);
    console_.info(message);
  }
  void warning(std::string_view message) override {
    if (verbosity_ >= 2) record("Warning: ", message);
    console_.warning(message);
  }
  void debug(std::string_view message) override { console_.debug(message); }
  void setVerbosity(int verbosity) {
    verbosity_ = verbosity;
    console_.setVerbosity(verbosity);
  }
  void startRecording() { recording_ = true; }
  void stopRecording() {
    recording_ = false;
    lines_.clear();
  }
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  void record(std::string_view prefix, std::string_view message) {
    if (recording_) lines_.push_back(std::string(prefix) + std::string(message));
  }
  ConsoleLog console_;
  int verbosity_;
  bool recording_ = false;
  std::vector<std::string> lines_;
};

// The current session of the API, with its log. Mesh objects handed out by current_mesh()
// share it; their arrays may view its mesh, so a mesh about to be replaced is kept (retired)
// while any of them lives.
struct LiveSession {
  LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  GeometryFactory& builtIn() { return session.factories().builtIn(); }
  // The factory that holds an entity: the built-in one when it does, else the OpenCASCADE one
  // (which reports an entity neither holds).
  GeometryFactory& factoryOf(EntityId id) { return builtIn().contains(id) ? builtIn() : *occ; }
  // Next free tags: the factories share the model, so a new tag must be free in both.
  int nextTag(int kind) const { return occ->maxTag(kind) + 1; }

  // A call recognised but not supported warns once per session: true the first time.
  bool firstWarning(const std::string& call) { return warnedCalls.insert(call).second; }

  // What scripts print (Printf) goes to sys.stdout, log lines to sys.stderr.
  PythonStream out{"stdout"};
  PythonStream err{"stderr"};
  RecordingLog log;
  Session session;
  GeometryFactory* occ = nullptr;
  std::string modelName;
  std::vector<std::unique_ptr<Mesh>> retired;
  std::set<std::string> warnedCalls;
  // The ONELAB parameters set from Python (onelab.set/setNumber/setString), by name.
  std::map<std::string, std::vector<double>> onelabNumbers;
  std::map<std::string, std::vector<std::string>> onelabStrings;
  // Colors given to options (option.setColor), read back by option.getColor.
  std::map<std::string, std::array<int, 4>> colors;
  // The options given to plugins (plugin.setNumber/setString), by plugin name.
  std::map<std::string, post::PluginOptions> pluginOptions;
};

// The module's state: the current session, made on first use.
class ApiState {
 public:
  LiveSession& live() {
    if (!current_) current_ = std::make_shared<LiveSession>();
    return *current_;
  }
  Session& session() { return live().session; }
  bool initialized() const { return current_ != nullptr; }
  void finalize() { current_.reset(); }
  std::shared_ptr<LiveSession> shared() {
    live();
    return current_;
  }
  // Before the mesh changes: when a Mesh object shares the session, the buffers its arrays
  // may view move to a retired mesh that lives as long as the session, and the session
  // continues with a copy.
  void meshWillChange();

 private:
  std::shared_ptr<LiveSession> current_;
};

using State = std::shared_ptr<ApiState>;

// Raises the module's exception `type` ("Error", "MeshError") with `message`.
[[noreturn]] void raiseError(const char* type, const std::string& message);
std::vector<EntityId> entityIds(const DimTags& dimTags);
pybind11::list dimTagList(const std::vector<EntityId>& ids);
// Synchronizes the session's model with its factories; what prevents it raises Error.
void synchronize(Session& session);

using Tags = std::vector<int>;

// A binding of a call on a list of tags: the next free tag of `kind` when the tag is -1, then
// add(session, tag, tags); returns the tag.
template <typename Add>
auto tagged(const State& state, int kind, Add add) {
  return [state, kind, add](const Tags& tags, int tag) {
    LiveSession& s = state->live();
    if (tag < 0) tag = s.nextTag(kind);
    add(s, tag, tags);
    return tag;
  };
}

// Extrusion layers as the API gives them; without heights, as many layers of equal height, as
// the reference spaces them (python/shape_operations.cpp).
ExtrusionLayers layersOf(const std::vector<int>& numElements, const std::vector<double>& heights,
                         bool recombine);

// Warns of a call recognised but not supported, once per session: "<call>: <why>".
void warnUnsupported(const State& state, const std::string& call, const std::string& why);

// geomesh.model.geo (with geo.mesh) and geomesh.model.occ.
void defineGeo(pybind11::module_& geo, const State& state);
void defineOcc(pybind11::module_& occ, const State& state);
// Transformations, copies, removals and queries of both kernels (python/shape_operations.cpp).
void defineGeoOperations(pybind11::module_& geo, const State& state);
void defineOccOperations(pybind11::module_& occ, const State& state);
// geomesh.model queries: boundaries, values, boxes; display calls (python/model_queries.cpp).
void defineModelQueries(pybind11::module_& model, const State& state);
// python/partition_api.cpp: mesh.partition, unpartition, and the partition entities' queries.
void definePartitions(pybind11::module_& model, pybind11::module_& mesh, const State& state);
// The partition entities of dimension `dim` (-1: all), listed after the model's own.
std::vector<EntityId> partitionEntityIds(const Session& session, int dim);
// The boundary of a partition entity (signed when `oriented`), or nullopt for the model's own.
std::optional<std::vector<EntityId>> partitionBoundary(const Session& session, EntityId id,
                                                       bool oriented);
// geomesh.model.mesh: fields, constraints, discrete surfaces (python/model_mesh_api.cpp).
void defineMeshConstraints(pybind11::module_& mesh, const State& state);
// geomesh.logger, fltk, graphics, onelab; option.setColor/getColor (python/misc_api.cpp).
void defineFrontEnds(pybind11::module_& m, pybind11::module_& option, const State& state);
// geomesh.view and geomesh.view.option (python/views_api.cpp); geomesh.plugin
// (python/plugin_api.cpp).
void defineViews(pybind11::module_& view, const State& state);
void definePlugins(pybind11::module_& plugin, const State& state);

}  // namespace geomesh::python
