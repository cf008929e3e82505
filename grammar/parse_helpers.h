// Small builders used by the grammar actions in parser.y, kept here so the actions stay short.
#pragma once

#include "grammar/ast.h"
#include "grammar/parser.hpp"

namespace geomesh {
class Lexer;
}

namespace geomesh::grammar {

SourceLocation at(const Parser::location_type& where);
ast::ExprPtr makeExpr(ast::ExprKind kind, const Parser::location_type& where);
ast::ExprPtr unary(std::string op, ast::ExprPtr operand, const Parser::location_type& where);
ast::ExprPtr binary(std::string op, ast::ExprPtr left, ast::ExprPtr right,
                    const Parser::location_type& where);
// {a} stands for a itself; {a, b} for the list.
ast::ExprPtr listOrSingle(ast::ExprList items, const Parser::location_type& where);

template <class Node>
ast::StmtPtr makeStmt(Node node, const Parser::location_type& where) {
  auto stmt = std::make_unique<ast::Stmt>();
  stmt->loc = at(where);
  stmt->node = std::move(node);
  return stmt;
}

// name[index]: an item of a list, or a call when `name` is a built-in function (Str[...]).
ast::ExprPtr elementOrCall(ast::Name name, ast::ExprPtr index, const Parser::location_type& where);

// S2N[text] / NS::S2N[text]: the Struct whose name `text` evaluates to (`function` must be S2N).
ast::ExprPtr structByString(ast::Name function, std::string space, ast::ExprPtr text,
                            const Parser::location_type& where);
// NameStruct[NS::#i]: a call whose one argument counts in the namespace (a Count node naming
// it in its words).
ast::ExprPtr indexInNamespace(ast::Name function, std::string space, ast::ExprPtr index,
                              const Parser::location_type& where);

ast::StmtPtr shapeCommand(ast::ExprPtr shape, const Parser::location_type& where);
// Whether `words "*"` selects every entity of a kind (Recombine Surface "*"), and that
// selection as the shape words{:}.
bool selectsEverything(const std::vector<std::string>& words, const ast::Expr& bare);
ast::ExprPtr everything(std::vector<std::string> words, const Parser::location_type& where);
ast::StmtPtr forStmt(ast::Name variable, ast::ExprPtr range, ast::StmtList body,
                     const Parser::location_type& where);

// Throws a SyntaxError saying what was expected where, in words a user understands.
[[noreturn]] void reportSyntaxError(const Lexer& lexer, const Parser::context& context);

}  // namespace geomesh::grammar
