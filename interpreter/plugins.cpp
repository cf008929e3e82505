// Plugins in batch: their options are kept per plugin; Run executes the ones geomesh has
// (SimplePartition) and says so for the others, which act on post-processing views.
#include <array>

#include "api/partitioning.h"
#include "interpreter/script_interpreter.h"
#include "stdlib/clamped_integer.h"

namespace geomesh {

namespace {

double optionOr(const std::map<std::string, double>& options, const std::string& name,
                double fallback) {
  const auto it = options.find(name);
  return it == options.end() ? fallback : it->second;
}

}  // namespace

void Interpreter::executePlugin(const ast::PluginStmt& plugin, const SourceLocation& where) {
  if (plugin.value) {
    const Value value = evaluate(*plugin.value);
    // Text options (expressions, file names) belong to plugins geomesh does not run.
    if (value.isNumeric() && value.size() == 1)
      pluginOptions_[plugin.plugin][plugin.member] = value.numbers().front();
    return;
  }
  if (plugin.member != "Run") {
    warn(where,
         "'Plugin(" + plugin.plugin + ")." + plugin.member + "' is not a plugin action; ignored");
    return;
  }
  if (plugin.plugin != "SimplePartition") {
    warn(where, "Plugin(" + plugin.plugin + ") is not supported yet; ignored");
    return;
  }
  const auto& options = pluginOptions_[plugin.plugin];
  std::array<int, 3> slices{};
  const char* names[] = {"NumSlicesX", "NumSlicesY", "NumSlicesZ"};
  for (int k = 0; k < 3; ++k) {
    const int n = clampedInteger<int>(optionOr(options, names[k], 1));
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
