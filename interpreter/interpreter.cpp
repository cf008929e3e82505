// Statements of a script: For, If, macros, Call, Include, and located errors and warnings.
#include "interpreter/run_script.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "api/session.h"
#include "grammar/parse.h"
#include "interpreter/diagnostics.h"
#include "interpreter/script_interpreter.h"
#include "stdlib/edit_distance.h"

namespace geomesh {

namespace {

std::optional<std::string> readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

void runScriptFile(Session& session, const std::string& path) {
  Interpreter(session).runFile(path);
}

void runScriptText(Session& session, const std::string& text, const std::string& name) {
  Interpreter(session).runText(text, name);
}

// Values given by -setnumber / -setstring are variables before the script starts: the
// script reads them directly, and DefineConstant leaves them as they are.
Interpreter::Interpreter(Session& session) : session_(session), functions_(builtinFunctions()) {
  for (const auto& [name, value] : session.numberOverrides())
    variables_[name] = Value::number(value);
  for (const auto& [name, value] : session.stringOverrides())
    variables_[name] = Value::string(value);
  session.factories().onHandover(
      [this](const UnsupportedOperation& unsupported) { reportHandover(unsupported); });
}

Interpreter::~Interpreter() {
  session_.factories().onHandover(nullptr);
}

void Interpreter::runFile(const std::string& path) {
  auto text = readFile(path);
  if (!text) throw ScriptError(SourceLocation{path, 1, 1}, "cannot open file '" + path + "'", "");
  runText(*text, path);
}

void Interpreter::runText(const std::string& text, const std::string& name) {
  std::error_code ignored;
  includeStack_.push_back(std::filesystem::weakly_canonical(name, ignored).string());
  try {
    runSource(name, text);
  } catch (const AbortScript&) {
  }
  includeStack_.pop_back();
}

void Interpreter::runSource(const std::string& name, std::string text) {
  sources_.push_back(SourceFile{name, std::move(text)});
  try {
    programs_.push_back(parseScript(name, sources_.back().text));
  } catch (const SyntaxError& error) {
    fail(error.location(), error.what());
  }
  execute(programs_.back());
}

void Interpreter::execute(const ast::StmtList& statements) {
  for (const auto& statement : statements) execute(*statement);
}

void Interpreter::execute(const ast::Stmt& statement) {
  const SourceLocation& where = statement.loc;
  statementLocation_ = &where;
  std::visit(
      [&](const auto& node) {
        using Node = std::decay_t<decltype(node)>;
        if constexpr (std::is_same_v<Node, ast::AssignStmt>) executeAssign(node, where);
        if constexpr (std::is_same_v<Node, ast::OptionAssignStmt>) executeOptionAssign(node, where);
        if constexpr (std::is_same_v<Node, ast::CommandStmt>) executeCommand(node, where);
        if constexpr (std::is_same_v<Node, ast::ForStmt>) executeFor(node, where);
        if constexpr (std::is_same_v<Node, ast::IfStmt>) executeIf(node);
        if constexpr (std::is_same_v<Node, ast::MacroStmt>) defineMacro(node, where);
        if constexpr (std::is_same_v<Node, ast::CallStmt>) executeCall(node, where);
        if constexpr (std::is_same_v<Node, ast::DefineConstantStmt>) executeDefineConstant(node);
        if constexpr (std::is_same_v<Node, ast::PluginStmt>) executePlugin(node, where);
      },
      statement.node);
}

// For i In {a:b:c} counts from a by c (default 1, whatever the direction), adding c each
// time, while it has not passed b; afterwards i holds the first value past the end, as in
// Gmsh. Other lists are walked item by item and leave i at the last item.
void Interpreter::executeFor(const ast::ForStmt& loop, const SourceLocation& where) {
  const ast::Expr* range = loop.range.get();
  if (range->kind == ast::ExprKind::List && range->args.size() == 1 &&
      range->args[0]->kind == ast::ExprKind::Range)
    range = range->args[0].get();
  const std::string variable = loop.variable.base.empty() ? "" : resolveName(loop.variable);
  std::vector<double> values;
  double after = 0;
  if (range->kind == ast::ExprKind::Range) {
    const double first = evaluateNumber(*range->args[0]);
    const double last = evaluateNumber(*range->args[1]);
    const double step = range->args.size() > 2 ? evaluateNumber(*range->args[2]) : 1.0;
    if (step == 0) fail(range->loc, "loop step must not be zero");
    if ((last - first) / step + 1 > maxLoopIterations()) failTooManyIterations(where);
    double value = first;
    for (; step > 0 ? value <= last : value >= last; value += step) values.push_back(value);
    after = value;
  } else {
    values = evaluateNumbers(*range);
    if (static_cast<double>(values.size()) > maxLoopIterations()) failTooManyIterations(where);
    if (!values.empty()) after = values.back();
  }
  for (double value : values) {
    if (!variable.empty()) variables_[variable] = Value::number(value);
    execute(loop.body);
  }
  if (!variable.empty() && (range->kind == ast::ExprKind::Range || !values.empty()))
    variables_[variable] = Value::number(after);
}

double Interpreter::maxLoopIterations() const {
  return session_.options().number("General.MaxLoopIterations");
}

void Interpreter::failTooManyIterations(const SourceLocation& where) const {
  fail(where, "loop has more than " + std::to_string(static_cast<long long>(maxLoopIterations())) +
                  " iterations; General.MaxLoopIterations sets the limit");
}

void Interpreter::executeIf(const ast::IfStmt& branches) {
  for (const auto& branch : branches.branches) {
    if (evaluateNumber(*branch.condition) != 0) {
      execute(branch.body);
      return;
    }
  }
  execute(branches.elseBody);
}

// A second definition of a macro is ignored with a warning: Gmsh keeps the first too.
void Interpreter::defineMacro(const ast::MacroStmt& macro, const SourceLocation& where) {
  if (!macros_.emplace(macro.name, &macro.body).second)
    warn(where, "macro '" + macro.name + "' is already defined; this definition is ignored");
}

void Interpreter::executeCall(const ast::CallStmt& call, const SourceLocation& where) {
  const ast::Expr& expr = *call.name;
  // Call Name; names the macro itself, even when a variable is called Name too (as in Gmsh);
  // a string expression gives the name otherwise: Call "Name"; Call StrCat("Na", "me");
  std::string name;
  if (expr.kind == ast::ExprKind::Variable && expr.name.suffixes.empty())
    name = expr.name.base;
  else
    name = evaluateString(expr);
  auto macro = macros_.find(name);
  if (macro == macros_.end()) {
    std::vector<std::string> known;
    for (const auto& [macroName, body] : macros_) known.push_back(macroName);
    fail(expr.loc, "unknown macro '" + name + "'" + didYouMean(name, known));
  }
  const double maxDepth = session_.options().number("General.MaxMacroDepth");
  if (callDepth_ >= maxDepth)
    fail(where, "macro calls nested deeper than " +
                    std::to_string(static_cast<long long>(maxDepth)) + " (endless recursion of '" +
                    name + "'?); General.MaxMacroDepth sets the limit");
  ++callDepth_;
  try {
    execute(*macro->second);
  } catch (...) {
    --callDepth_;
    throw;
  }
  --callDepth_;
}

std::string Interpreter::directoryOf(const std::string& file) const {
  return std::filesystem::path(file).parent_path().string();
}

void Interpreter::executeInclude(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.args.size() != 1) fail(where, "Include takes one file name");
  std::filesystem::path path = evaluateString(*command.args[0]);
  if (path.is_relative()) path = std::filesystem::path(directoryOf(where.file)) / path;
  const std::string shown = path.lexically_normal().string();
  std::error_code ignored;
  const std::string canonical = std::filesystem::weakly_canonical(path, ignored).string();
  for (const auto& open : includeStack_)
    if (open == canonical)
      fail(command.args[0]->loc, "include cycle: '" + shown + "' is already being read");
  // Only regular files: a device such as /dev/zero would be read forever.
  auto text = std::filesystem::is_regular_file(path, ignored) ? readFile(shown) : std::nullopt;
  if (!text) fail(command.args[0]->loc, "cannot open include file '" + shown + "'");
  includeStack_.push_back(canonical);
  try {
    runSource(shown, std::move(*text));
  } catch (ScriptError& error) {
    includeStack_.pop_back();
    error.addIncludedFrom(where);
    throw;
  } catch (...) {
    includeStack_.pop_back();
    throw;
  }
  includeStack_.pop_back();
}

void Interpreter::fail(const SourceLocation& where, const std::string& message) const {
  std::string_view line;
  for (auto it = sources_.rbegin(); it != sources_.rend(); ++it) {
    if (it->name == where.file) {
      line = it->lineText(where.line);
      break;
    }
  }
  throw ScriptError(where, message, line);
}

// Each place warns once, even inside a loop or a macro called many times.
void Interpreter::warn(const SourceLocation& where, const std::string& message) const {
  std::string text = where.file + ":" + std::to_string(where.line) + ":" +
                     std::to_string(where.column) + ": warning: " + message;
  if (!warned_.insert(text).second) return;
  session_.log().warning(text);
}

std::string Interpreter::didYouMean(std::string_view name,
                                    const std::vector<std::string>& candidates) const {
  auto close = closestNames(name, candidates, 1);
  return close.empty() ? std::string() : "; did you mean '" + close.front() + "'?";
}

}  // namespace geomesh
