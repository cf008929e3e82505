// Meshing a session's model, with failures traced back to the script that built it.
#pragma once

#include "api/session.h"

namespace geomesh::api {

// Synchronizes, then meshes the model up to `dim` (0 to 3). A MeshError on an entity whose
// defining statement the session recorded becomes a ScriptError at that statement (the line
// quoted from its file, when readable); any other MeshError passes as is.
void generate(Session& session, int dim);

// SetOrder n;: gives the session's mesh the order n with the session's other Mesh.* options,
// failures located as generate's are.
void setOrder(Session& session, int order);

// When statements were ignored as not supported yet and the model has no entity of dimension
// 0 to `dim`, the script described nothing geomesh can mesh: throws a ScriptError at the first
// ignored statement, naming how many there were. Does nothing when no statement was ignored.
void requireSomethingToMesh(Session& session, int dim);

}  // namespace geomesh::api
