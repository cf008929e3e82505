// Statements of the language itself: Printf, Error, Warning, SetFactory, SetNumber, SystemCall;
// and options (General.X = ...).
#include <cstdlib>
#include <cmath>
#include <fstream>
#include <filesystem>

#include "interpreter/diagnostics.h"
#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "stdlib/colors.h"

namespace geomesh {

namespace {

// Options of post-processing, printing and solvers: they change nothing in a batch mesh run,
// except the Print. options the registry holds (the size of pictures written).
bool isInterfaceOption(std::string_view path) {
  for (std::string_view category : {"Print.", "PostProcessing.", "Solver."})
    if (path.starts_with(category)) return true;
  return false;
}

bool isOptionCategory(std::string_view path) {
  return path.starts_with("General.") || path.starts_with("Geometry.") ||
         path.starts_with("Mesh.");
}

}  // namespace

// The value an option takes from `op` ("=", "+=", "-=", "*=", "/=") and its operand.
double Interpreter::applyAssignment(double old, double operand, const std::string& op) {
  if (op == "+=") return old + operand;
  if (op == "-=") return old - operand;
  if (op == "*=") return old * operand;
  if (op == "/=") return old / operand;
  return operand;
}

// Error(...) and Warning(...) report a message of the script's at the statement.
void Interpreter::executeMessage(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle != ast::CommandStmt::Args::Paren || command.args.empty())
    return unsupportedStatement(command, where);
  const std::string message = command.args.size() == 1 ? evaluateString(*command.args[0])
                                                       : format(command.args, where, true);
  if (command.words.front() == "Error") fail(where, message);
  warn(where, message);
}

// SetFactory("OpenCASCADE"); SetFactory("Built-in"); select the geometry factory; other
// kernels warn.
void Interpreter::executeSetFactory(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.args.size() == 1) {
    if (session_.factories().select(evaluateString(*command.args[0]))) return;
  }
  unsupportedStatement(command, where);
}

// SystemCall "command"; runs a shell command, only when the user allowed it on the command
// line (-allow_system_calls): a script received from elsewhere runs nothing by surprise.
void Interpreter::executeSystemCall(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.args.size() != 1)
    fail(where, "'" + command.words.front() + "' takes one command, as in SystemCall \"ls\";");
  const std::string shellCommand = evaluateString(*command.args[0]);
  if (!session_.systemCallsAllowed()) {
    warn(where, "'" + command.words.front() + "' refused: running \"" + shellCommand +
                    "\" needs -allow_system_calls on the command line; ignored");
    return;
  }
  session_.out().flush();
  const int status = std::system(shellCommand.c_str());
  if (status != 0)
    warn(where, "\"" + shellCommand + "\" exited with status " + std::to_string(status));
}

void Interpreter::executePrintf(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle != ast::CommandStmt::Args::Paren || command.args.empty())
    fail(where, "Printf takes a format string and values, as in Printf(\"x = %g\", x)");
  const std::string line = command.args.size() == 1 ? evaluateString(*command.args[0])
                                                    : format(command.args, where, true);
  if (!command.redirectTarget) {
    // Script output is a "direct" message: shown from verbosity 3 up, as in Gmsh.
    if (session_.options().number("General.Verbosity") >= 3) session_.out() << line << '\n';
    return;
  }
  std::filesystem::path path = evaluateString(*command.redirectTarget);
  if (session_.sandboxed()) {
    warn(where, "Printf into '" + path.string() + "' skipped: this session writes no file");
    return;
  }
  if (path.is_relative()) path = std::filesystem::path(directoryOf(where.file)) / path;
  std::ofstream file(path, command.redirect == ">>" ? std::ios::app : std::ios::trunc);
  if (!file) fail(command.redirectTarget->loc, "cannot write to '" + path.string() + "'");
  file << line << '\n';
}

// SetNumber("name", x); SetString("name", "s"); set parameters, read back by GetNumber /
// GetString. Like Gmsh, they leave options alone even when the name is an option's.
void Interpreter::executeSetter(const ast::CommandStmt& command, const SourceLocation& where) {
  const std::string& head = command.words.front();
  if (command.args.size() != 2) fail(where, "'" + head + "' takes a name and a value");
  const std::string key = evaluateString(*command.args[0]);
  if (head == "SetNumber")
    parameterNumbers_[key] = evaluateNumber(*command.args[1]);
  else
    parameterStrings_[key] = evaluateString(*command.args[1]);
}

void Interpreter::executeOptionAssign(const ast::OptionAssignStmt& assign,
                                      const SourceLocation& where) {
  if (assign.path.starts_with("View.")) return setViewOption(assign, where);
  if (isInterfaceOption(assign.path) && !session_.options().find(assign.path)) {
    session_.log().debug(where.file + ":" + std::to_string(where.line) + ": option '" +
                         assign.path + "' has no effect in batch mode");
    return;
  }
  if (executeFieldOption(assign, where)) return;
  if ((!isOptionCategory(assign.path) && !session_.options().find(assign.path)) ||
      assign.index) {
    warn(where, "option '" + assign.path + "' is not supported yet; ignored");
    return;
  }
  OptionRegistry& options = session_.options();
  const auto* option = options.find(assign.path);
  if (!option) {
    // Setting an option that does not exist changes nothing: warn and go on, as scripts
    // written for other versions set options this one does not know.
    warn(where, "unknown option '" + assign.path + "'; ignored" +
                    didYouMean(assign.path, options.suggestions(assign.path)));
    return;
  }
  const ast::Expr& rhs = *assign.value;
  if (option->type == OptionType::Color && rhs.kind == ast::ExprKind::Variable &&
      rhs.name.suffixes.empty() && !variables_.contains(rhs.name.base)) {
    // A colour name: Mesh.Color.Triangles = LightBlue;
    if (auto color = namedColor(rhs.name.base)) {
      options.setNumber(assign.path, *color);
      return;
    }
    warn(rhs.loc, "unknown colour '" + rhs.name.base + "'; ignored" +
                      didYouMean(rhs.name.base, colorNames()));
    return;
  }
  Value value = evaluate(rhs);
  if (option->type == OptionType::String) {
    if (value.kind() != Value::Kind::String || assign.op != "=")
      fail(rhs.loc, "option '" + assign.path + "' takes a string");
    options.setString(assign.path, value.strings()[0]);
    return;
  }
  if (!value.isNumeric()) fail(rhs.loc, "option '" + assign.path + "' takes a number");
  const auto& xs = value.numbers();
  double number = xs.empty() ? 0 : xs[0];
  if (option->type == OptionType::Color && xs.size() >= 3)
    number = std::round(xs[0]) * 65536 + std::round(xs[1]) * 256 + std::round(xs[2]);
  else if (xs.size() != 1)
    fail(rhs.loc, "option '" + assign.path + "' takes a single number");
  options.setNumber(assign.path, applyAssignment(options.number(assign.path), number, assign.op));
  optionChanged(option->name);
}

// Options the geometry kernel reads while entities are defined take effect at once.
void Interpreter::optionChanged(const std::string& name) {
  if (name == "Geometry.Tolerance")
    session_.factory().setTolerance(session_.options().number("Geometry.Tolerance"));
}

Value Interpreter::optionValue(const ast::Expr& expr) {
  if (auto view = viewOptionValue(expr)) return *view;
  if ((!isOptionCategory(expr.text) && !session_.options().find(expr.text)) ||
      !expr.args.empty()) {
    warn(expr.loc, "option '" + expr.text + "' is not supported yet; reads as 0");
    return Value::number(0);
  }
  const OptionRegistry& options = session_.options();
  const auto* option = options.find(expr.text);
  if (!option)
    fail(expr.loc, "unknown option '" + expr.text + "'" +
                       didYouMean(expr.text, options.suggestions(expr.text)));
  if (option->type == OptionType::String) return Value::string(option->text);
  if (auto statistic = modelStatistic(option->name)) return Value::number(*statistic);
  return Value::number(option->number);
}

}  // namespace geomesh
