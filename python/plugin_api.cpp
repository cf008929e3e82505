// geomesh.plugin: the options of the session's plugins and running them, as a script's
// Plugin(Name).Option = v; Plugin(Name).Run; does (mesh/views/plugins.h).
#include <pybind11/pybind11.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "grammar/diagnostic.h"
#include "interpreter/run_script.h"
#include "mesh/sizes/named_formula.h"
#include "python/api_state.h"

namespace py = pybind11;

namespace geomesh::python {
namespace {

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

// SimplePartition, Simplify and Fair change the mesh or the merged triangles rather than the
// views: the interpreter runs them, given the options as script statements.
bool runsInInterpreter(const std::string& name) {
  return name == "SimplePartition" || name == "Simplify" || name == "Fair";
}

void runInInterpreter(Session& session, const std::string& name,
                      const post::PluginOptions& options) {
  std::string text;
  for (const auto& [option, value] : options.numbers) {
    char number[32];
    std::snprintf(number, sizeof number, "%.17g", value);
    text += "Plugin(" + name + ")." + option + " = " + number + ";\n";
  }
  for (const auto& [option, value] : options.strings)
    text += "Plugin(" + name + ")." + option + " = " + quoted(value) + ";\n";
  text += "Plugin(" + name + ").Run;\n";
  try {
    runScriptText(session, text, (std::filesystem::current_path() / "<plugin>").string());
  } catch (const ScriptError& e) {
    raiseError("Error", e.message());
  }
}

// Runs a plugin; the tag of the view it made, -1 when it made none.
int runPlugin(const State& state, const std::string& name) {
  LiveSession& live = state->live();
  const post::PluginOptions& options = live.pluginOptions[name];
  Session& session = live.session;
  const std::size_t before = session.views().size();
  if (runsInInterpreter(name)) {
    if (name == "SimplePartition") state->meshWillChange();
    runInInterpreter(session, name, options);
  } else {
    post::PluginContext context{session.views(), session.mesh(), session.log(),
                                compileNamedFormula,
                                [&session] { return session.mergedTriangulation(); }};
    post::PluginOutcome outcome = post::PluginOutcome::Unknown;
    try {
      outcome = post::runPlugin(name, options, context);
    } catch (const post::PluginError& e) {
      raiseError("Error", e.what());
    }
    if (outcome == post::PluginOutcome::Unknown)
      raiseError("Error", "unknown plugin '" + name + "'");
    if (outcome == post::PluginOutcome::DisplayOnly)
      session.log().debug("Plugin(" + name + ") changes only the display");
  }
  const post::ViewStore& views = session.views();
  return views.size() > before ? views.at(views.size() - 1).tag : -1;
}

}  // namespace

void definePlugins(py::module_& plugin, const State& state) {
  plugin.def(
      "setNumber",
      [state](const std::string& name, const std::string& option, double value) {
        state->live().pluginOptions[name].numbers[option] = value;
      },
      py::arg("name"), py::arg("option"), py::arg("value"),
      "Sets a number option of a plugin, as Plugin(name).option = value; does.");
  plugin.def(
      "setString",
      [state](const std::string& name, const std::string& option, const std::string& value) {
        state->live().pluginOptions[name].strings[option] = value;
      },
      py::arg("name"), py::arg("option"), py::arg("value"),
      "Sets a string option of a plugin.");
  plugin.def(
      "run", [state](const std::string& name) { return runPlugin(state, name); },
      py::arg("name"),
      "Runs a plugin with the options set so far, as Plugin(name).Run; does; returns the tag "
      "of the view it made, -1 when it made none. An unknown plugin raises Error.");
}

}  // namespace geomesh::python
