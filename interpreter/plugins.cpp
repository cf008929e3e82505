// Plugins in batch: their options are kept per plugin; Run executes the plugin on the
// session's views (mesh/views/plugins.h) or, for SimplePartition, partitions the mesh.
#include <array>

#include "api/partitioning.h"
#include "api/session.h"
#include "interpreter/script_interpreter.h"
#include "mesh/sizes/named_formula.h"
#include "stdlib/clamped_integer.h"

namespace geomesh {

void Interpreter::executePlugin(const ast::PluginStmt& plugin, const SourceLocation& where) {
  if (plugin.value) {
    const Value value = evaluate(*plugin.value);
    post::PluginOptions& options = pluginOptions_[plugin.plugin];
    if (value.isNumeric() && value.size() == 1)
      options.numbers[plugin.member] = value.numbers().front();
    else if (value.isText() && value.size() == 1)
      options.strings[plugin.member] = value.strings().front();
    else
      fail(plugin.value->loc, "'Plugin(" + plugin.plugin + ")." + plugin.member +
                                  "' takes one number or one text");
    return;
  }
  if (plugin.member != "Run") {
    warn(where,
         "'Plugin(" + plugin.plugin + ")." + plugin.member + "' is not a plugin action; ignored");
    return;
  }
  if (plugin.plugin == "SimplePartition") return partitionBySlices(where);
  post::PluginContext context{session_.views(), session_.mesh(), session_.log(),
                              compileNamedFormula};
  post::PluginOutcome outcome;
  try {
    outcome = post::runPlugin(plugin.plugin, pluginOptions_[plugin.plugin], context);
  } catch (const post::PluginError& error) {
    fail(where, error.what());
  }
  if (outcome == post::PluginOutcome::Unknown) {
    session_.noteIgnoredStatement(where);
    warn(where, "Plugin(" + plugin.plugin + ") is not a plugin geomesh has; ignored");
  } else if (outcome == post::PluginOutcome::DisplayOnly) {
    session_.log().debug(where.file + ":" + std::to_string(where.line) + ": Plugin(" +
                         plugin.plugin + ") changes only the display");
  }
}

// Plugin(SimplePartition): NumSlicesX/Y/Z slices of the mesh's bounding box.
void Interpreter::partitionBySlices(const SourceLocation& where) {
  const post::PluginOptions& options = pluginOptions_["SimplePartition"];
  std::array<int, 3> slices{};
  const char* names[] = {"NumSlicesX", "NumSlicesY", "NumSlicesZ"};
  for (int k = 0; k < 3; ++k) {
    const int n = clampedInteger<int>(options.number(names[k], 1));
    if (n < 1)
      fail(where, std::string("Plugin(SimplePartition).") + names[k] + " must be at least 1");
    slices[k] = n;
  }
  if (session_.sandboxed()) {
    warn(where, "'Plugin(SimplePartition).Run' skipped: this session meshes nothing");
    return;
  }
  try {
    api::partitionMeshBySlices(session_, slices);
  } catch (const std::exception& error) {
    fail(where, error.what());
  }
}

}  // namespace geomesh
