// The model API's state: the current session, shared by the functions of python/model_api.cpp
// and python/model_geometry.cpp, and the helpers both use.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "api/session.h"
#include "app/console_log.h"
#include "kernel/geometry_factory.h"

namespace geomesh::python {

using DimTags = std::vector<std::pair<int, int>>;

// The current session of the API, with its log. Mesh objects handed out by current_mesh()
// share it; their arrays may view its mesh, so a mesh about to be replaced is kept (retired)
// while any of them lives.
struct LiveSession {
  LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  GeometryFactory& builtIn() { return session.factories().builtIn(); }
  // Next free tags: the factories share the model, so a new tag must be free in both.
  int nextTag(int kind) const { return occ->maxTag(kind) + 1; }

  ConsoleLog log;
  Session session;
  GeometryFactory* occ = nullptr;
  std::string modelName;
  std::vector<std::unique_ptr<Mesh>> retired;
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

// geomesh.model.geo (with geo.mesh) and geomesh.model.occ.
void defineGeo(pybind11::module_& geo, const State& state);
void defineOcc(pybind11::module_& occ, const State& state);

}  // namespace geomesh::python
