// Plugins that scripts run in batch (Plugin(Name).Option = v; Plugin(Name).Run;): each reads
// views (or the mesh) and adds or changes views, with the reference's option names.
#pragma once

#include <functional>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/messages.h"
#include "mesh/core/mesh.h"
#include "mesh/discrete/triangulation.h"
#include "mesh/views/view.h"

namespace geomesh::post {

// The options a script gave a plugin, by name: numbers and texts apart.
struct PluginOptions {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> strings;
  double number(const std::string& name, double fallback) const;
  std::string text(const std::string& name, const std::string& fallback) const;
};

// A formula of a plugin option (MathEval's Expression0...), compiled once: evaluating it takes
// the values of the variables in the order they were named when compiling.
using CompiledFormula = std::function<double(std::span<const double> values)>;
// Compiles `text` over the named variables (x, y, z, v0..v8, w0..w8, Time, TimeStep); throws
// (any std::exception, its message saying why) when the text is not a formula. The session
// fills it from its expression evaluator; without one, formula plugins throw PluginError.
using FormulaCompiler =
    std::function<CompiledFormula(const std::string& text, const std::vector<std::string>& variables)>;

// What a plugin works on: the session's views, its mesh (may be empty) and where messages go;
// and, for the plugins on surfaces, the session's merged triangulation (STL, ...) when it has
// no surface mesh: null (or an empty function) when there is none.
struct PluginContext {
  ViewStore& views;
  const Mesh& mesh;
  MessageSink& log;
  FormulaCompiler compileFormula = {};
  std::function<const Triangulation*()> mergedTriangles = {};
};

// A plugin's options are wrong (no such view, a bad expression...): the message says which.
struct PluginError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class PluginOutcome { Ran, DisplayOnly, Unknown };

// Runs plugin `name`: Ran when it did its work, DisplayOnly for plugins that only change
// the display (Annotate, ...: nothing to do in batch), Unknown for names geomesh does not
// know. Throws PluginError. SimplePartition, Simplify and Fair are not here: they change the
// session's mesh or merged triangulation (interpreter/plugins.cpp).
PluginOutcome runPlugin(const std::string& name, const PluginOptions& options,
                        PluginContext& context);

}  // namespace geomesh::post
