// Node builders for the grammar actions, the nesting bound, and syntax error messages.
#include "grammar/parse_helpers.h"

#include <algorithm>
#include <map>

#include "grammar/keywords.h"
#include "grammar/tokenizer.h"

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

namespace {

// Evaluating and destroying an expression recurse once per nested operator: a bound keeps
// absurd inputs (a sum of a million terms) from exhausting the stack.
constexpr int kMaxExpressionDepth = 2000;

void setDepth(Expr& expr, const Parser::location_type& where) {
  for (const auto& arg : expr.args) expr.depth = std::max(expr.depth, arg->depth + 1);
  if (expr.depth > kMaxExpressionDepth)
    throw SyntaxError(at(where), "expression too deeply nested (more than " +
                                     std::to_string(kMaxExpressionDepth) + " operators)");
}

}  // namespace

ExprPtr unary(std::string op, ExprPtr operand, const Parser::location_type& where) {
  auto expr = makeExpr(ExprKind::Unary, where);
  expr->text = std::move(op);
  expr->args.push_back(std::move(operand));
  setDepth(*expr, where);
  return expr;
}

ExprPtr binary(std::string op, ExprPtr left, ExprPtr right, const Parser::location_type& where) {
  auto expr = makeExpr(ExprKind::Binary, where);
  expr->text = std::move(op);
  expr->args.push_back(std::move(left));
  expr->args.push_back(std::move(right));
  setDepth(*expr, where);
  return expr;
}

ExprPtr listOrSingle(ExprList items, const Parser::location_type& where) {
  if (items.size() == 1 && items[0]->kind != ExprKind::Range) return std::move(items[0]);
  auto list = makeExpr(ExprKind::List, where);
  list->args = std::move(items);
  return list;
}

ExprPtr elementOrCall(Name name, ExprPtr index, const Parser::location_type& where) {
  const bool call = name.suffixes.empty() && isFunctionName(name.base);
  auto expr = makeExpr(call ? ExprKind::Call : ExprKind::Element, where);
  if (call)
    expr->text = std::move(name.base);
  else
    expr->name = std::move(name);
  expr->args.push_back(std::move(index));
  return expr;
}

ExprPtr structByString(Name function, std::string space, ExprPtr text,
                       const Parser::location_type& where) {
  if (function.base != "S2N" || !function.suffixes.empty())
    throw SyntaxError(at(where), "expected S2N[...] before '.' to name a Struct by a string");
  auto ref = makeExpr(ExprKind::Member, where);
  ref->words.push_back(std::move(space));
  ref->name.suffixes.push_back(std::move(text));
  return ref;
}

ExprPtr indexInNamespace(Name function, std::string space, ExprPtr index,
                         const Parser::location_type& where) {
  if (!function.suffixes.empty() || function.base != "NameStruct")
    throw SyntaxError(at(where), "'" + function.base + "' takes no namespace index (NS::#i)");
  auto count = makeExpr(ExprKind::Count, where);
  count->words.push_back(std::move(space));
  count->args.push_back(std::move(index));
  auto call = makeExpr(ExprKind::Call, where);
  call->text = std::move(function.base);
  call->args.push_back(std::move(count));
  return call;
}

StmtPtr shapeCommand(ExprPtr shape, const Parser::location_type& where) {
  CommandStmt command;
  command.words = shape->words;
  command.shape = std::move(shape);
  return makeStmt(std::move(command), where);
}

bool selectsEverything(const std::vector<std::string>& words, const Expr& bare) {
  if (words.size() < 2 || bare.kind != ExprKind::String || bare.text != "*") return false;
  const std::string& kind = words.back();
  return kind == "Point" || kind == "Line" || kind == "Curve" || kind == "Surface" ||
         kind == "Volume";
}

ExprPtr everything(std::vector<std::string> words, const Parser::location_type& where) {
  auto shape = makeExpr(ExprKind::Shape, where);
  shape->words = std::move(words);
  shape->parts.emplace_back();
  shape->parts.back().items.push_back(makeExpr(ExprKind::All, where));
  return shape;
}

StmtPtr forStmt(Name variable, ExprPtr range, StmtList body, const Parser::location_type& where) {
  return makeStmt(ForStmt{std::move(variable), std::move(range), std::move(body)}, where);
}

namespace {

// Token names for messages: keywords and operators in quotes, categories as words.
std::string describe(Parser::symbol_kind_type kind) {
  std::string_view name = Parser::symbol_name(kind);
  for (std::string_view category :
       {"number", "string", "identifier", "keyword", "modifier", "attribute", "end of file"})
    if (name == category) return std::string(name);
  if (name.starts_with('\'')) return std::string(name);
  std::string quoted(1, '\'');
  quoted.append(name);
  quoted.push_back('\'');
  return quoted;
}

SourceLocation endOf(const Parser::location_type& where) {
  return SourceLocation{where.end.filename ? *where.end.filename : std::string(), where.end.line,
                        where.end.column};
}

}  // namespace

namespace {

// Tokens that could only continue an expression or a name: listing them says nothing useful.
bool continuesExpression(std::string_view name) {
  for (std::string_view op : {"'+'", "'-'", "'*'", "'/'", "'%'", "'^'", "'<'", "'>'", "'=='",
                              "'!='", "'<='", "'>='", "'&&'", "'||'", "'?'", "':'", "'['", "'~'",
                              "'('", "'.'", "'++'", "'--'", "'+='", "'-='", "'*='", "'/='"})
    if (name == op) return true;
  return false;
}

bool contains(const std::vector<std::string>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? " or " : ", ";
    text += names[i];
  }
  return text;
}

// At the end of the file, what is missing is the closing of the innermost open bracket or
// block: point at where it was opened, which may be far above the end.
void reportUnclosed(const Lexer& lexer) {
  const Lexer::OpenToken* open = lexer.innermostOpen();
  if (!open) return;
  static const std::map<std::string, std::string> closers = {
      {"For", "EndFor"}, {"If", "EndIf"}, {"Macro", "Return"}, {"Function", "Return"},
      {"(", ")"},        {"[", "]"},      {"{", "}"}};
  auto it = closers.find(open->text);
  const std::string closer = it == closers.end() ? "its end" : "'" + it->second + "'";
  throw SyntaxError(at(open->where), "'" + open->text + "' is never closed: " + closer +
                                         " expected before the end of the file");
}

}  // namespace

void reportSyntaxError(const Lexer& lexer, const Parser::context& context) {
  Parser::symbol_kind_type kinds[Parser::YYNTOKENS];
  const int count = context.expected_tokens(kinds, Parser::YYNTOKENS);
  std::vector<std::string> expected;
  for (int i = 0; i < count; ++i) expected.push_back(describe(kinds[i]));
  const bool atEnd = context.token() == Parser::symbol_kind::S_YYEOF;
  const std::string found = atEnd ? "end of file" : "'" + lexer.currentText() + "'";
  const bool atStatementStart = contains(expected, "'For'");
  if (contains(expected, "';'") && !atStatementStart && !lexer.previousText().empty())
    throw SyntaxError(endOf(lexer.previousLocation()),
                      "expected ';' after '" + lexer.previousText() + "' (found " + found + ")");
  if (atEnd) reportUnclosed(lexer);
  std::vector<std::string> useful;
  for (const auto& name : expected)
    if (!continuesExpression(name)) useful.push_back(name);
  std::string message = "unexpected " + found;
  if (contains(useful, "number"))
    message += ", expected an expression";
  else if (!useful.empty() && useful.size() <= 6)
    message += ", expected " + listed(useful);
  throw SyntaxError(at(context.location()), message);
}

}  // namespace geomesh::grammar
