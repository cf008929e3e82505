// Meshing with failures located in the script.
#include "api/meshing.h"

#include <algorithm>
#include <fstream>
#include <iterator>

#include "api/partitioning.h"
#include "grammar/diagnostic.h"
#include "mesh/core/mesh_error.h"
#include "mesh/pipeline/generate.h"

namespace geomesh::api {

namespace {

// Line `line` of a script file, for quoting in a diagnostic; empty if unreadable.
std::string sourceLine(const std::string& path, int line) {
  std::ifstream in(path, std::ios::binary);
  SourceFile file{path, {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()}};
  return std::string(file.lineText(line));
}

[[noreturn]] void failAt(const SourceLocation& where, const std::string& message) {
  throw ScriptError(where, message, sourceLine(where.file, where.line));
}

// "point or curve", "point, curve or surface", ...
std::string entityKinds(int dim) {
  static const char* const kKinds[] = {"point", "curve", "surface", "volume"};
  std::string text = kKinds[0];
  for (int d = 1; d <= dim; ++d) text += (d == dim ? " or " : ", ") + std::string(kKinds[d]);
  return text;
}

bool hasEntityUpTo(const Model& model, int dim) {
  for (int d = 0; d <= dim; ++d)
    if (!model.entities(d).empty()) return true;
  return false;
}

// The statement that defined the entity; for an entity made as part of a larger one (a face
// of a Sphere, of a merged STEP part, of a Boolean's result), that of the first entity above
// it that a statement defined.
std::optional<SourceLocation> originOf(const Session& session, EntityId entity) {
  std::vector<EntityId> level{entity};
  while (!level.empty()) {
    for (const EntityId& e : level)
      if (auto where = session.origin(e)) return where;
    std::vector<EntityId> above;
    for (const EntityId& e : level)
      if (e.dim < 3)
        for (int tag : session.model().upward(e)) above.push_back({e.dim + 1, tag});
    std::sort(above.begin(), above.end());
    above.erase(std::unique(above.begin(), above.end()), above.end());
    level = std::move(above);
  }
  return std::nullopt;
}

}  // namespace

void generate(Session& session, int dim) {
  try {
    session.generate(dim);
  } catch (const MeshError& error) {
    // Point at the statement that defined the entity, when the script did.
    if (auto where = originOf(session, error.entity)) failAt(*where, error.what());
    throw;
  }
}

void setOrder(Session& session, int order) {
  MeshOptions options = session.meshOptions();
  options.elementOrder = order;
  // The pieces of a partitioned mesh hold its elements: made again for the new ones.
  const MeshPartitions* partitions = session.mesh().partitions();
  const int partitionCount = partitions ? partitions->count : 0;
  session.mesh().clearPartitions();
  try {
    raiseOrder(session.model(), options, session.mesh(), session.log());
    if (partitionCount > 0) partitionMesh(session, partitionCount);
  } catch (const MeshError& error) {
    if (auto where = originOf(session, error.entity)) failAt(*where, error.what());
    throw;
  }
}

void requireSomethingToMesh(Session& session, int dim) {
  const auto first = session.firstIgnoredStatement();
  if (!first) return;
  session.synchronize();
  if (hasEntityUpTo(session.model(), dim)) return;
  const std::size_t count = session.ignoredStatementCount();
  const std::string ignored = count == 1 ? " statement was ignored as not supported yet (this one)"
                                         : " statements were ignored as not supported yet (the "
                                           "first here)";
  failAt(*first, "nothing to mesh: " + std::to_string(count) + ignored + " and the model has no " +
                     entityKinds(dim));
}

}  // namespace geomesh::api
