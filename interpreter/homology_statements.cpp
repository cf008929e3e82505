// Homology and Cohomology statements: each records a request that the session carries out
// once the mesh is generated (mesh/homology/homology.h).
//
//   Homology;                                  the whole mesh, every dimension
//   Homology {1, 2};                           domain: physical groups 1 and 2
//   Homology {{1}, {70, 71}};                  domain {1} relative to subdomain {70, 71}
//   Cohomology(1) {{1}, {70, 71}};             only the bases of dimension 1 are saved
#include "api/session.h"
#include "interpreter/script_interpreter.h"
#include "stdlib/clamped_integer.h"

namespace geomesh {

namespace {

bool isList(const ast::Expr& e) {
  return e.kind == ast::ExprKind::List;
}

}  // namespace

void Interpreter::requestHomology(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.words.size() != 1 || !command.op.empty() || !command.tail.empty())
    return unsupportedStatement(command, where);
  const std::string& keyword = command.words.front();
  const bool withDims = command.argStyle == ast::CommandStmt::Args::Paren;
  if (withDims && !command.shape)
    fail(where, keyword + "(dimensions) needs its domain: " + keyword +
                    "(dimensions) {{domain}, {subdomain}};");
  if (command.argStyle == ast::CommandStmt::Args::Bare ||
      command.argStyle == ast::CommandStmt::Args::Bracket ||
      (command.shape && (command.shape->parts.size() != 1 || command.shape->parts[0].isBlock)))
    fail(where, "expected " + keyword + "; or " + keyword + " {{domain}, {subdomain}}; or " +
                    keyword + "(dimensions) {{domain}, {subdomain}};");

  auto integers = [&](const std::vector<double>& values) {
    std::vector<int> out;
    for (double v : values) {
      if (v != static_cast<double>(static_cast<long long>(v)))
        fail(where,
             keyword + ": physical tags and dimensions are integers, not " + std::to_string(v));
      out.push_back(clampedInteger<int>(v));
    }
    return out;
  };

  HomologyRequest request;
  request.kind = keyword == "Homology" ? HomologyKind::Homology : HomologyKind::Cohomology;
  request.origin =
      where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
  if (withDims) request.dims = integers(evaluateNumbers(command.args));
  if (command.shape) {
    const ast::ExprList& items = command.shape->parts[0].items;
    const bool lists = !items.empty() && isList(*items.front());
    if (!lists) {
      request.domain = integers(evaluateNumbers(items));  // Homology {1, 2};
    } else {
      if (items.size() > 2)
        fail(where, keyword + " takes {{domain}, {subdomain}}: " + std::to_string(items.size()) +
                        " lists given");
      request.domain = integers(evaluateNumbers(*items[0]));
      if (items.size() == 2) request.subdomain = integers(evaluateNumbers(*items[1]));
    }
  }
  session_.homologyRequests().push_back(std::move(request));
}

}  // namespace geomesh
