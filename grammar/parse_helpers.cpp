#include "grammar/parse_helpers.h"

#include <algorithm>

#include "grammar/lexer.h"

namespace geomesh::grammar {

using namespace ast;

SourceLocation at(const Parser::location_type& where) {
  return SourceLocation{where.begin.filename ? *where.begin.filename : std::string(),
                        where.begin.line, where.begin.column};
}

ExprPtr makeExpr(ExprKind kind, const Parser::location_type& where) {
  auto expr = std::make_unique<Expr>();
  expr->kind = kind;
  expr->loc = at(where);
  return expr;
}

ExprPtr unary(std::string op, ExprPtr operand, const Parser::location_type& where) {
  auto expr = makeExpr(ExprKind::Unary, where);
  expr->text = std::move(op);
  expr->args.push_back(std::move(operand));
  return expr;
}

ExprPtr binary(std::string op, ExprPtr left, ExprPtr right, const Parser::location_type& where) {
  auto expr = makeExpr(ExprKind::Binary, where);
  expr->text = std::move(op);
  expr->args.push_back(std::move(left));
  expr->args.push_back(std::move(right));
  return expr;
}

ExprPtr listOrSingle(ExprList items, const Parser::location_type& where) {
  if (items.size() == 1 && items[0]->kind != ExprKind::Range) return std::move(items[0]);
  auto list = makeExpr(ExprKind::List, where);
  list->args = std::move(items);
  return list;
}

StmtPtr shapeCommand(ExprPtr shape, const Parser::location_type& where) {
  CommandStmt command;
  command.words = shape->words;
  command.shape = std::move(shape);
  return makeStmt(std::move(command), where);
}

StmtPtr forStmt(Name variable, ExprPtr range, StmtList body, const Parser::location_type& where) {
  return makeStmt(ForStmt{std::move(variable), std::move(range), std::move(body)}, where);
}

namespace {

std::string describe(Parser::symbol_kind_type kind) {
  std::string_view name = Parser::symbol_name(kind);
  if (name.size() < 2 || name.front() != '"' || name.back() != '"') return std::string(name);
  std::string quoted(1, '\'');
  quoted.append(name.substr(1, name.size() - 2));
  quoted.push_back('\'');
  return quoted;
}

SourceLocation endOf(const Parser::location_type& where) {
  return SourceLocation{where.end.filename ? *where.end.filename : std::string(), where.end.line,
                        where.end.column};
}

}  // namespace

void reportSyntaxError(const Lexer& lexer, const Parser::context& context) {
  constexpr int kMaxExpected = 8;
  Parser::symbol_kind_type expected[kMaxExpected];
  int count = context.expected_tokens(expected, kMaxExpected);
  const bool semicolonExpected = std::any_of(expected, expected + count, [](auto kind) {
    return std::string_view(Parser::symbol_name(kind)) == "';'";
  });
  const bool atEnd = context.token() == Parser::symbol_kind::S_YYEOF;
  const std::string found = atEnd ? "end of file" : "'" + lexer.currentText() + "'";
  if (semicolonExpected && !lexer.previousText().empty())
    throw SyntaxError(endOf(lexer.previousLocation()),
                      "expected ';' after '" + lexer.previousText() + "' (found " + found + ")");
  std::string message = "unexpected " + found;
  if (count > 0 && count < kMaxExpected) {
    message += ", expected ";
    for (int i = 0; i < count; ++i) {
      if (i > 0) message += i + 1 == count ? " or " : ", ";
      message += describe(expected[i]);
    }
  }
  throw SyntaxError(at(context.location()), message);
}

}  // namespace geomesh::grammar
