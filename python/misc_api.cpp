// The front-end namespaces of the API: geomesh.logger (the log recorded for Python),
// geomesh.fltk and geomesh.graphics (no graphical interface: they do nothing, and say so),
// geomesh.onelab (parameters kept in the session, for scripts that read back what they set)
// and the display colors of geomesh.option.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <chrono>
#include <ctime>
#include <string>
#include <vector>

#include "python/api_state.h"

namespace py = pybind11;

namespace geomesh::python {
namespace {

void defineLogger(py::module_& logger, const State& state) {
  logger.def(
      "start", [state] { state->live().log.startRecording(); },
      "Starts recording the log's messages for get().");
  logger.def(
      "get", [state] { return state->live().log.lines(); },
      "The messages recorded since start(): ['Info: ...', 'Warning: ...'].");
  logger.def(
      "stop", [state] { state->live().log.stopRecording(); },
      "Stops recording and forgets what was recorded.");
  logger.def(
      "write",
      [state](const std::string& message, const std::string& level) {
        MessageSink& log = state->live().log;
        if (level == "warning" || level == "error")
          log.warning(message);
        else
          log.info(message);
      },
      py::arg("message"), py::arg("level") = "info", "Logs a message (info, warning, error).");
  logger.def("getWallTime", [] {
    using namespace std::chrono;
    return duration<double>(system_clock::now().time_since_epoch()).count();
  });
  logger.def("getCpuTime",
             [] { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; });
  logger.def("getLastError", [] { return std::string(); });
}

// geomesh.fltk: there is no graphical interface; the calls that would show one say so.
void defineFltk(py::module_& fltk, const State& state) {
  auto noInterface = [state] {
    state->live().log.info("There is no graphical interface: nothing to show");
  };
  fltk.def(
      "isAvailable", [] { return 0; }, "0: there is no graphical interface.");
  fltk.def("run", noInterface, "Logs that there is no graphical interface, and returns.");
  fltk.def(
      "wait", [noInterface](double) { noInterface(); }, py::arg("time") = -1.,
      "Logs that there is no graphical interface, and returns.");
  fltk.def("initialize", noInterface, "Logs that there is no graphical interface.");
  for (const char* name : {"finalize", "update", "awake", "lock", "unlock"})
    fltk.def(name, [] {}, "Nothing to do without a graphical interface.");
  fltk.def(
      "selectEntities", [](int) { return py::make_tuple(0, py::list()); }, py::arg("dim") = -1,
      "Nothing to select without a graphical interface: (0, []).");
}

// geomesh.onelab: the parameters a script sets, read back by name. Nothing runs a client.
void defineOnelab(py::module_& onelab, const State& state) {
  onelab.def(
      "set",
      [state](const std::string& data, const std::string& format) {
        if (format != "json") throw py::value_error("onelab.set reads JSON only");
        LiveSession& s = state->live();
        py::object parameters = py::module_::import("json").attr("loads")(data);
        if (py::isinstance<py::dict>(parameters)) parameters = py::list(py::make_tuple(parameters));
        for (const py::handle item : parameters) {
          const py::dict parameter = item.cast<py::dict>();
          if (!parameter.contains("name")) continue;
          const std::string name = parameter["name"].cast<std::string>();
          const std::string type =
              parameter.contains("type") ? parameter["type"].cast<std::string>() : "number";
          py::object values = parameter.contains("values") ? parameter["values"] : py::list();
          if (type == "number")
            s.onelabNumbers[name] = values.cast<std::vector<double>>();
          else
            s.onelabStrings[name] = values.cast<std::vector<std::string>>();
        }
      },
      py::arg("data"), py::arg("format") = "json",
      "Defines parameters from their JSON description (name, type, values).");
  onelab.def(
      "getNumber",
      [state](const std::string& name) {
        const auto& numbers = state->live().onelabNumbers;
        const auto it = numbers.find(name);
        return it == numbers.end() ? std::vector<double>{} : it->second;
      },
      py::arg("name"), "The values of a number parameter ([] when there is none).");
  onelab.def(
      "setNumber",
      [state](const std::string& name, const std::vector<double>& values) {
        state->live().onelabNumbers[name] = values;
      },
      py::arg("name"), py::arg("value"));
  onelab.def(
      "getString",
      [state](const std::string& name) {
        const auto& strings = state->live().onelabStrings;
        const auto it = strings.find(name);
        return it == strings.end() ? std::vector<std::string>{} : it->second;
      },
      py::arg("name"), "The values of a string parameter ([] when there is none).");
  onelab.def(
      "setString",
      [state](const std::string& name, const std::vector<std::string>& values) {
        state->live().onelabStrings[name] = values;
      },
      py::arg("name"), py::arg("value"));
  onelab.def(
      "getNames",
      [state](const std::string& search) {
        std::vector<std::string> names;
        LiveSession& s = state->live();
        for (const auto& [name, values] : s.onelabNumbers)
          if (name.find(search) != std::string::npos) names.push_back(name);
        for (const auto& [name, values] : s.onelabStrings)
          if (name.find(search) != std::string::npos) names.push_back(name);
        return names;
      },
      py::arg("search") = "");
  onelab.def(
      "clear",
      [state](const std::string& name) {
        LiveSession& s = state->live();
        if (name.empty()) {
          s.onelabNumbers.clear();
          s.onelabStrings.clear();
        }
        s.onelabNumbers.erase(name);
        s.onelabStrings.erase(name);
      },
      py::arg("name") = "");
  onelab.def(
      "run",
      [state](const std::string&, const std::string&) {
        warnUnsupported(state, "onelab.run", "there is no ONELAB client to run");
      },
      py::arg("name") = "", py::arg("command") = "");
}

void defineColors(py::module_& option, const State& state) {
  option.def(
      "setColor",
      [state](const std::string& name, int r, int g, int b, int a) {
        state->live().colors[name] = {r, g, b, a};
      },
      py::arg("name"), py::arg("r"), py::arg("g"), py::arg("b"), py::arg("a") = 255,
      "Keeps a display color (nothing is displayed); getColor reads it back.");
  option.def(
      "getColor",
      [state](const std::string& name) {
        const auto& colors = state->live().colors;
        const auto it = colors.find(name);
        const std::array<int, 4> rgba = it == colors.end() ? std::array<int, 4>{0, 0, 0, 255}
                                                           : it->second;
        return py::make_tuple(rgba[0], rgba[1], rgba[2], rgba[3]);
      },
      py::arg("name"), "The color setColor gave (r, g, b, a); (0, 0, 0, 255) otherwise.");
}

}  // namespace

void defineFrontEnds(py::module_& m, py::module_& option, const State& state) {
  py::module_ logger = m.def_submodule("logger", "The log's messages, recorded for Python.");
  defineLogger(logger, state);
  py::module_ fltk = m.def_submodule("fltk", "No graphical interface: calls that do nothing.");
  defineFltk(fltk, state);
  py::module_ graphics = m.def_submodule("graphics", "No graphics: draw does nothing.");
  graphics.def("draw", [] {}, "Nothing is drawn.");
  py::module_ onelab = m.def_submodule("onelab", "Parameters by name, set and read back.");
  defineOnelab(onelab, state);
  defineColors(option, state);
}

}  // namespace geomesh::python
