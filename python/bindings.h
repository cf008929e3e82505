// The parts of the compiled module `_geomesh`: the Mesh object (python/module.cpp) and the
// model-building API over one current session (python/model_api.cpp).
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <utility>

#include "api/session.h"

namespace geomesh::python {

// A session whose mesh Python reads: a finished script run, or the current session of the
// model API. `owner` keeps the session alive as long as the Python object, and every array
// that views the mesh's memory keeps that object alive.
class MeshResult {
 public:
  MeshResult(std::shared_ptr<void> owner, Session& session)
      : owner_(std::move(owner)), session_(&session) {}
  Session& session() { return *session_; }
  const Session& session() const { return *session_; }
  const Mesh& mesh() const { return session_->mesh(); }

 private:
  std::shared_ptr<void> owner_;
  Session* session_;
};

// geomesh.initialize/finalize/clear/write/merge/current_mesh and the submodules model,
// model.geo, model.geo.mesh, model.occ, model.mesh and option. Needs the module's Error and
// MeshError attributes and its Mesh class defined first.
void defineModelApi(pybind11::module_& m);

}  // namespace geomesh::python
