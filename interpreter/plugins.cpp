// Plugins in batch: their options are kept per plugin; Run executes the plugin on the
// session's views (mesh/views/plugins.h) or, for SimplePartition, partitions the mesh, and for
// Simplify and Fair changes the merged triangulation.
#include <array>
#include <cmath>
#include <cstdio>

#include "api/partitioning.h"
#include "api/session.h"
#include "interpreter/script_interpreter.h"
#include "mesh/sizes/named_formula.h"
#include "mesh/discrete/surface_fairing.h"
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
  if (plugin.plugin == "Simplify") return simplifyMergedTriangles(where);
  if (plugin.plugin == "Fair") return fairMergedTriangles(where);
  post::PluginContext context{session_.views(), session_.mesh(), session_.log(),
                              compileNamedFormula,
                              [this] { return session_.mergedTriangulation(); }};
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

// Plugin(Simplify): TargetTriangles (a count, 0: none) and MaxError (a distance, 0: none),
// at least one of them, on the merged triangles.
void Interpreter::simplifyMergedTriangles(const SourceLocation& where) {
  const post::PluginOptions& options = pluginOptions_["Simplify"];
  const double target = options.number("TargetTriangles", 0);
  const double maxError = options.number("MaxError", 0);
  if (!(target >= 0) || target != std::floor(target))
    fail(where, "Plugin(Simplify).TargetTriangles must be a whole number of triangles, 0 for none");
  if (!(maxError >= 0) || !std::isfinite(maxError))
    fail(where, "Plugin(Simplify).MaxError must be a distance, 0 for none");
  if (target == 0 && maxError == 0)
    fail(where,
         "Plugin(Simplify) needs TargetTriangles (a triangle count) or MaxError (a distance)");
  if (!session_.mergedTriangulation()) {
    warn(where, "Plugin(Simplify): there are no merged triangles (merge an STL, PLY or OFF "
                "file first); nothing done");
    return;
  }
  try {
    const auto [before, after] =
        session_.simplifyMergedTriangles(clampedInteger<std::size_t>(target), maxError);
    session_.log().info("Plugin(Simplify): " + std::to_string(before) + " -> " +
                        std::to_string(after) + " triangles");
  } catch (const std::runtime_error& error) {
    fail(where, error.what());
  }
}

// Plugin(Fair): Iterations (1) steps of mean-curvature flow of TimeStep (0.5, in squared mean
// edge lengths) on the merged triangles.
void Interpreter::fairMergedTriangles(const SourceLocation& where) {
  const post::PluginOptions& options = pluginOptions_["Fair"];
  FairingOptions fairing;
  const double iterations = options.number("Iterations", 1);
  fairing.step = options.number("TimeStep", fairing.step);
  if (!(iterations >= 1) || iterations != std::floor(iterations) || iterations > 1e6)
    fail(where, "Plugin(Fair).Iterations must be a whole number, at least 1");
  if (!(fairing.step > 0) || !std::isfinite(fairing.step))
    fail(where, "Plugin(Fair).TimeStep must be positive");
  fairing.iterations = int(iterations);
  if (!session_.mergedTriangulation()) {
    warn(where, "Plugin(Fair): there are no merged triangles (merge an STL, PLY or OFF file "
                "first); nothing done");
    return;
  }
  try {
    const double moved = session_.fairMergedTriangles(fairing);
    char text[64];
    std::snprintf(text, sizeof text, "%.6g", moved);
    session_.log().info("Plugin(Fair): " + std::to_string(fairing.iterations) +
                        " iteration(s); vertices moved by at most " + text);
  } catch (const std::runtime_error& error) {
    fail(where, error.what());
  }
}

}  // namespace geomesh
