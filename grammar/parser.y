// The .geo grammar (LALR(1)). Bison turns this file into generated/grammar/parser.cpp.
%require "3.8"
%language "c++"
%define api.namespace {geomesh}
%define api.parser.class {Parser}
%define api.token.constructor
%define api.value.type variant
%define api.filename.type {const std::string}
%define api.token.prefix {TOK_}
%define parse.error custom
%define parse.lac full
%locations
%param {Lexer& lexer}
%parse-param {ast::StmtList& program}

%code requires {
#include <string>
#include "grammar/ast.h"
namespace geomesh { class Lexer; }
}

%code {
#include "grammar/tokenizer.h"
#include "grammar/parse_helpers.h"

namespace geomesh {
inline Parser::symbol_type yylex(Lexer& lexer) { return lexer.next(); }
}
using namespace geomesh::ast;
using geomesh::grammar::at;
using geomesh::grammar::makeExpr;
using geomesh::grammar::makeStmt;
using geomesh::grammar::binary;
using geomesh::grammar::unary;
}

%token <double> NUMBER "number"
%token <std::string> STRING "string" IDENT "identifier" WORD "keyword"
%token <std::string> TAILWORD "modifier" ATTR "attribute"
%token FOR "For" ENDFOR "EndFor" IN "In" IF "If" ELSEIF "ElseIf" ELSE "Else" ENDIF "EndIf"
%token MACRO "Macro" RETURN "Return" CALL "Call" PLUGIN "Plugin" USINGWIRE "Using Wire"
%token STRUCT "Struct" SCOPE "::" DOTS "..." SPLIT "Split" INTERSECT "Intersect"
%token DEFINECONSTANT "DefineConstant" DEFINENUMBER "DefineNumber" DEFINESTRING "DefineString"
%token EQ "==" NE "!=" LE "<=" GE ">=" AND "&&" OR "||" INCR "++" DECR "--"
%token PLUSEQ "+=" MINUSEQ "-=" TIMESEQ "*=" DIVEQ "/=" APPEND ">>"

%nterm <ast::StmtList> stmts block_body else_part
%nterm <ast::StmtPtr> stmt command control
%nterm <std::vector<ast::IfStmt::Branch>> elseifs
%nterm <ast::Name> name
%nterm <ast::LValue> lvalue
%nterm <std::string> assign_op compound_op
%nterm <std::vector<std::string>> words
%nterm <ast::ExprPtr> expr primary shape bare item option_path struct_def struct_name struct_ref
%nterm <ast::ExprPtr> member_ref periodic_tag
%nterm <std::string> struct_append member_name
%nterm <std::vector<ast::Attribute>> struct_members
%nterm <ast::Attribute> struct_member
%nterm <ast::ExprList> args args_opt items
%nterm <std::vector<ast::ViewItem>> view_items
%nterm <ast::ViewItem> view_item
%nterm <std::vector<ast::ShapePart>> parts
%nterm <ast::ShapePart> part block block_part
%nterm <std::vector<ast::ShapePart>> block_parts
%nterm <ast::ExprPtr> block_item
%nterm <std::vector<ast::TailItem>> tail
%nterm <ast::TailItem> tail_item
%nterm <std::vector<ast::ConstantDef>> constants
%nterm <ast::ConstantDef> constant
%nterm <std::vector<ast::Attribute>> attributes pairs
%nterm <ast::Attribute> attribute pair

%right '?' ':'
%left OR
%left AND
%left EQ NE
%left '<' '>' LE GE
%left '+' '-'
%left '*' '/' '%'
%precedence '!' UNARY
%right '^'

%%

program: stmts { program = std::move($1); } ;

stmts:
  %empty { }
| stmts stmt { $$ = std::move($1); if ($2) $$.push_back(std::move($2)); }
;

stmt:
  ';' { $$ = nullptr; }
| lvalue assign_op expr ';' {
    $$ = makeStmt(AssignStmt{std::move($1), std::move($2), std::move($3)}, @1); }
| lvalue INCR ';' { $$ = makeStmt(AssignStmt{std::move($1), "++", nullptr}, @1); }
| lvalue DECR ';' { $$ = makeStmt(AssignStmt{std::move($1), "--", nullptr}, @1); }
| option_path assign_op expr ';' {
    auto path = std::move($1);
    $$ = makeStmt(OptionAssignStmt{std::move(path->text),
                                   path->args.empty() ? nullptr : std::move(path->args[0]),
                                   std::move($2), std::move($3)}, @1); }
| command { $$ = std::move($1); }
| control { $$ = std::move($1); }
| struct_def ';' {
    CommandStmt c; c.words.push_back("Struct"); c.argStyle = CommandStmt::Args::Bare;
    c.args.push_back(std::move($1)); $$ = makeStmt(std::move(c), @1); }
| member_ref assign_op expr ';' {
    CommandStmt c; c.words.push_back("Struct"); c.argStyle = CommandStmt::Args::Bare;
    c.args.push_back(std::move($1)); c.op = std::move($2); c.value = std::move($3);
    $$ = makeStmt(std::move(c), @1); }
;

// Struct NS::Name (Append) [ Tag 3, epsr 5, mu {1, 2}, label "iron", Enum, A, B ]
struct_def:
  STRUCT struct_name struct_append '[' ']' {
    $$ = std::move($2); $$->kind = ExprKind::StructDef; $$->loc = at(@1);
    $$->text = std::move($3); }
| STRUCT struct_name struct_append '[' struct_members ']' {
    $$ = std::move($2); $$->kind = ExprKind::StructDef; $$->loc = at(@1);
    $$->text = std::move($3); $$->attributes = std::move($5); }
;
struct_name:
  name { $$ = makeExpr(ExprKind::Member, @1); $$->words.emplace_back(); $$->name = std::move($1); }
| IDENT SCOPE name {
    $$ = makeExpr(ExprKind::Member, @1); $$->words.push_back(std::move($1));
    $$->name = std::move($3); }
;
// A Struct named in the text, or by a string: S2N["name"], NS::S2N[s] (an empty base name
// with the string as its only suffix).
struct_ref:
  struct_name { $$ = std::move($1); }
| name '[' expr ']' { $$ = grammar::structByString(std::move($1), "", std::move($3), @1); }
| IDENT SCOPE name '[' expr ']' {
    $$ = grammar::structByString(std::move($3), std::move($1), std::move($5), @1); }
;
struct_append:
  %empty { }
| '(' IDENT ')' {
    if ($2 != "Append") throw SyntaxError(at(@2), "expected '(Append)' after the Struct name");
    $$ = std::move($2); }
;
struct_members:
  struct_member { $$.push_back(std::move($1)); }
| struct_members ',' struct_member { $$ = std::move($1); $$.push_back(std::move($3)); }
;
struct_member:
  member_name { $$.name = std::move($1); $$.loc = at(@1); }
| member_name expr { $$.name = std::move($1); $$.loc = at(@1); $$.values.push_back(std::move($2)); }
;
member_name: IDENT { $$ = std::move($1); } | WORD { $$ = std::move($1); }
           | TAILWORD { $$ = std::move($1); } ;
member_ref: struct_ref '.' IDENT { $$ = std::move($1); $$->text = std::move($3); } ;

assign_op: '=' { $$ = "="; } | compound_op { $$ = std::move($1); } ;
compound_op: PLUSEQ { $$ = "+="; } | MINUSEQ { $$ = "-="; } | TIMESEQ { $$ = "*="; }
           | DIVEQ { $$ = "/="; } ;

name:
  IDENT { $$.base = std::move($1); }
| name '~' '{' expr '}' { $$ = std::move($1); $$.suffixes.push_back(std::move($4)); }
;

lvalue:
  name { $$.name = std::move($1); }
| name '[' ']' { $$.form = LValue::Form::List; $$.name = std::move($1); }
| name '(' ')' {
    $$.form = LValue::Form::List; $$.parenthesized = true; $$.name = std::move($1); }
| name '[' expr ']' {
    $$.form = LValue::Form::Element; $$.name = std::move($1); $$.index = std::move($3); }
| name '(' expr ')' {
    $$.form = LValue::Form::Element; $$.parenthesized = true; $$.name = std::move($1);
    $$.index = std::move($3); }
;

option_path:
  WORD '.' IDENT { $$ = makeExpr(ExprKind::Option, @1); $$->text = $1 + "." + $3; }
| WORD '[' expr ']' '.' IDENT {
    $$ = makeExpr(ExprKind::Option, @1); $$->text = $1 + "." + $6;
    $$->args.push_back(std::move($3)); }
| option_path '.' IDENT { $$ = std::move($1); $$->text += "." + $3; }
;

words:
  WORD { $$.push_back(std::move($1)); }
| words WORD { $$ = std::move($1); $$.push_back(std::move($2)); }
;

command:
  words ';' { CommandStmt c; c.words = std::move($1); $$ = makeStmt(std::move(c), @1); }
| words bare ';' {
    if (grammar::selectsEverything($1, *$2)) {  // Recombine Surface "*";
      $$ = grammar::shapeCommand(grammar::everything(std::move($1), @1), @1);
    } else {
      CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Bare;
      c.args.push_back(std::move($2)); $$ = makeStmt(std::move(c), @1);
    } }
| words STRING '=' expr ';' {  // Transfinite Curve "*" = 10;
    if ($2 != "*") throw SyntaxError(at(@2), "only \"*\" (every entity) may stand here");
    $$ = grammar::shapeCommand(grammar::everything(std::move($1), @1), @1);
    auto& c = std::get<CommandStmt>($$->node); c.op = "="; c.value = std::move($4); }
| words STRING '=' expr tail ';' {
    if ($2 != "*") throw SyntaxError(at(@2), "only \"*\" (every entity) may stand here");
    $$ = grammar::shapeCommand(grammar::everything(std::move($1), @1), @1);
    auto& c = std::get<CommandStmt>($$->node); c.op = "="; c.value = std::move($4);
    c.tail = std::move($5); }
| words '(' args_opt ')' ';' {
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Paren;
    c.args = std::move($3); $$ = makeStmt(std::move(c), @1); }
| words '(' args_opt ')' part ';' {  // Homology(1) {{domain}, {subdomain}};
    if ($1.size() != 1 || ($1[0] != "Homology" && $1[0] != "Cohomology")) {
      SourceLocation after = at(@4);  // just after ')', as for any other missing ';'
      after.line = @4.end.line; after.column = @4.end.column;
      throw SyntaxError(after, "expected ';' after ')' (found '{')");
    }
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Paren;
    c.args = std::move($3);
    auto s = makeExpr(ExprKind::Shape, @5); s->words = c.words; s->parts.push_back(std::move($5));
    c.shape = std::move(s); $$ = makeStmt(std::move(c), @1); }
| words '(' args_opt ')' '>' expr ';' {
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Paren;
    c.args = std::move($3); c.redirect = ">"; c.redirectTarget = std::move($6);
    $$ = makeStmt(std::move(c), @1); }
| words '(' args_opt ')' APPEND expr ';' {
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Paren;
    c.args = std::move($3); c.redirect = ">>"; c.redirectTarget = std::move($6);
    $$ = makeStmt(std::move(c), @1); }
| words '(' args_opt ')' assign_op expr ';' {
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Paren;
    c.args = std::move($3); c.op = std::move($5); c.value = std::move($6);
    $$ = makeStmt(std::move(c), @1); }
| words '(' args_opt ')' assign_op expr tail ';' {
    // Surface(1) = {1} Using Point{5}; Surface(1) = {1} In Sphere{7};
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Paren;
    c.args = std::move($3); c.op = std::move($5); c.value = std::move($6);
    c.tail = std::move($7); $$ = makeStmt(std::move(c), @1); }
| WORD '[' expr ']' '=' expr ';' {
    CommandStmt c; c.words.push_back(std::move($1)); c.argStyle = CommandStmt::Args::Bracket;
    c.args.push_back(std::move($3)); c.op = "="; c.value = std::move($6);
    $$ = makeStmt(std::move(c), @1); }
| WORD '[' expr ']' '=' WORD ';' {
    CommandStmt c; c.words.push_back(std::move($1)); c.argStyle = CommandStmt::Args::Bracket;
    c.args.push_back(std::move($3)); c.op = "=";
    c.value = makeExpr(ExprKind::String, @6); c.value->text = std::move($6);
    $$ = makeStmt(std::move(c), @1); }
| words WORD '[' expr ']' ';' {
    CommandStmt c; c.words = std::move($1); c.words.push_back(std::move($2));
    c.argStyle = CommandStmt::Args::Bracket; c.args.push_back(std::move($4));
    $$ = makeStmt(std::move(c), @1); }
| words WORD '[' expr ']' expr ';' {  // Save View[0] "file.pos";
    CommandStmt c; c.words = std::move($1); c.words.push_back(std::move($2));
    c.argStyle = CommandStmt::Args::Bracket; c.args.push_back(std::move($4));
    c.args.push_back(std::move($6)); $$ = makeStmt(std::move(c), @1); }
| words STRING '{' view_items '}' {
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Bare;
    auto name = makeExpr(ExprKind::String, @2); name->text = std::move($2);
    c.args.push_back(std::move(name)); c.viewItems = std::move($4);
    $$ = makeStmt(std::move(c), @1); }
| words '(' args_opt ')' assign_op block_parts ';' {
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Paren;
    c.args = std::move($3); c.op = std::move($5);
    auto s = makeExpr(ExprKind::Shape, @6); s->parts = std::move($6); c.value = std::move(s);
    $$ = makeStmt(std::move(c), @1); }
| words '=' expr ';' {
    CommandStmt c; c.words = std::move($1); c.op = "="; c.value = std::move($3);
    $$ = makeStmt(std::move(c), @1); }
| words periodic_tag '{' items '}' '=' periodic_tag '{' items '}' ';' {
    // The older periodicity form: Periodic Surface s {curves} = m {curves};
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Bare;
    auto slaveCurves = makeExpr(ExprKind::List, @3); slaveCurves->args = std::move($4);
    auto masterCurves = makeExpr(ExprKind::List, @8); masterCurves->args = std::move($9);
    c.args.push_back(std::move($2)); c.args.push_back(std::move(slaveCurves));
    c.args.push_back(std::move($7)); c.args.push_back(std::move(masterCurves));
    $$ = makeStmt(std::move(c), @1); }
| words IDENT part '=' bare part ';' {
    // Periodic Surface s {curves} = m {curves}; with the tags in variables
    if ($3.isBlock || $6.isBlock) throw SyntaxError(at(@3), "expected the lists of curves");
    CommandStmt c; c.words = std::move($1); c.argStyle = CommandStmt::Args::Bare;
    auto slave = makeExpr(ExprKind::Variable, @2); slave->name.base = std::move($2);
    auto slaveCurves = makeExpr(ExprKind::List, @3); slaveCurves->args = std::move($3.items);
    auto masterCurves = makeExpr(ExprKind::List, @6); masterCurves->args = std::move($6.items);
    c.args.push_back(std::move(slave)); c.args.push_back(std::move(slaveCurves));
    c.args.push_back(std::move($5)); c.args.push_back(std::move(masterCurves));
    $$ = makeStmt(std::move(c), @1); }
| words IDENT parts {
    CommandStmt c; c.words = std::move($1); c.colorName = std::move($2);
    auto s = makeExpr(ExprKind::Shape, @1); s->words = c.words; s->parts = std::move($3);
    c.shape = std::move(s); $$ = makeStmt(std::move(c), @1); }
| shape { $$ = grammar::shapeCommand(std::move($1), @1); }
| shape USINGWIRE part {
    $$ = grammar::shapeCommand(std::move($1), @1);
    auto wire = makeExpr(ExprKind::Shape, @2); wire->words = {"Wire"};
    wire->parts.push_back(std::move($3));
    std::get<CommandStmt>($$->node).tail.push_back(TailItem{"Using", std::move(wire)}); }
| SPLIT shape shape ';' {  // Split Curve{1} Point{2};
    $2->words.insert($2->words.begin(), "Split");
    $$ = grammar::shapeCommand(std::move($2), @1);
    std::get<CommandStmt>($$->node).tail.push_back(TailItem{"", std::move($3)}); }
| shape tail ';' {
    $$ = grammar::shapeCommand(std::move($1), @1);
    std::get<CommandStmt>($$->node).tail = std::move($2); }
| shape '=' expr ';' {
    $$ = grammar::shapeCommand(std::move($1), @1);
    auto& c = std::get<CommandStmt>($$->node); c.op = "="; c.value = std::move($3); }
| shape '=' expr tail ';' {
    $$ = grammar::shapeCommand(std::move($1), @1);
    auto& c = std::get<CommandStmt>($$->node); c.op = "="; c.value = std::move($3);
    c.tail = std::move($4); }
| shape '=' expr shape ';' {
    $$ = grammar::shapeCommand(std::move($1), @1);
    auto& c = std::get<CommandStmt>($$->node); c.op = "="; c.value = std::move($3);
    c.tail.push_back(TailItem{"", std::move($4)}); }
;

// A surface tag in the older periodicity form: a number (a name or a parenthesized
// expression there would make the grammar ambiguous).
periodic_tag:
  NUMBER { $$ = makeExpr(ExprKind::Number, @1); $$->number = $1; }
| name '[' expr ']' { $$ = grammar::elementOrCall(std::move($1), std::move($3), @1); }
;

bare:
  STRING { $$ = makeExpr(ExprKind::String, @1); $$->text = std::move($1); }
| NUMBER { $$ = makeExpr(ExprKind::Number, @1); $$->number = $1; }
| '-' NUMBER { $$ = makeExpr(ExprKind::Number, @1); $$->number = -$2; }
| name { $$ = makeExpr(ExprKind::Variable, @1); $$->name = std::move($1); }
| IDENT '(' args_opt ')' {
    $$ = makeExpr(ExprKind::Call, @1); $$->text = std::move($1); $$->args = std::move($3); }
;

tail: tail_item { $$.push_back(std::move($1)); }
    | tail tail_item { $$ = std::move($1); $$.push_back(std::move($2)); } ;
tail_item:
  TAILWORD { $$.word = std::move($1); }
| IN { $$.word = "In"; }
| TAILWORD expr { $$.word = std::move($1); $$.value = std::move($2); }
| IN expr { $$.word = "In"; $$.value = std::move($2); }
;

shape:
  words parts {
    $$ = makeExpr(ExprKind::Shape, @1); $$->words = std::move($1); $$->parts = std::move($2); }
;
parts: part { $$.push_back(std::move($1)); }
     | parts part { $$ = std::move($1); $$.push_back(std::move($2)); } ;
part:
  '{' '}' { }
| '{' items '}' { $$.items = std::move($2); }
| block_part { $$ = std::move($1); }
;
block_part: '{' block '}' { $$ = std::move($2); } ;
// After the first block, `{}` is an empty block: BooleanFragments(1) = { Volume{1:3}; }{};
block_parts: block_part { $$.push_back(std::move($1)); }
           | block_parts block_part { $$ = std::move($1); $$.push_back(std::move($2)); }
           | block_parts '{' '}' { $$ = std::move($1); $$.emplace_back(); } ;

// The data of a post-processing view: SP(x,y,z){v}; T2(x,y,0){"text"}; TIME{0,1}; ...
view_items: %empty { } | view_items view_item { $$ = std::move($1); $$.push_back(std::move($2)); } ;
view_item:
  IDENT '(' args_opt ')' '{' args_opt '}' ';' {
    $$.type = std::move($1); $$.hasCoordinates = true; $$.coordinates = std::move($3);
    $$.values = std::move($6); $$.loc = at(@1); }
| IDENT '{' args_opt '}' ';' {
    $$.type = std::move($1); $$.values = std::move($3); $$.loc = at(@1); }
;
block:
  block_item { $$.isBlock = true; $$.items.push_back(std::move($1)); }
| block block_item { $$ = std::move($1); $$.items.push_back(std::move($2)); }
;
block_item:
  shape ';' { $$ = std::move($1); }
| words ';' { $$ = makeExpr(ExprKind::Shape, @1); $$->words = std::move($1); }
| words bare ';' {  // Recombine 1; inside an extrusion
    $$ = makeExpr(ExprKind::Shape, @1); $$->words = std::move($1);
    $$->args.push_back(std::move($2)); }
| TAILWORD IDENT '[' expr ']' ';' {  // Using Index[1]; inside an extrusion along normals
    $$ = makeExpr(ExprKind::Shape, @1); $$->words = {std::move($1), std::move($2)};
    $$->args.push_back(std::move($4)); }
| TAILWORD WORD '[' expr ']' ';' {  // Using View[0];
    $$ = makeExpr(ExprKind::Shape, @1); $$->words = {std::move($1), std::move($2)};
    $$->args.push_back(std::move($4)); }
;

control:
  FOR '(' expr ':' expr ')' stmts ENDFOR {
    auto range = makeExpr(ExprKind::Range, @3);
    range->args.push_back(std::move($3)); range->args.push_back(std::move($5));
    $$ = grammar::forStmt(Name{}, std::move(range), std::move($7), @1); }
| FOR '(' expr ':' expr ':' expr ')' stmts ENDFOR {
    auto range = makeExpr(ExprKind::Range, @3);
    range->args.push_back(std::move($3)); range->args.push_back(std::move($5));
    range->args.push_back(std::move($7));
    $$ = grammar::forStmt(Name{}, std::move(range), std::move($9), @1); }
| FOR name IN expr stmts ENDFOR {
    $$ = grammar::forStmt(std::move($2), std::move($4), std::move($5), @1); }
| IF '(' expr ')' stmts elseifs else_part ENDIF {
    IfStmt s;
    s.branches.push_back(IfStmt::Branch{std::move($3), std::move($5)});
    for (auto& b : $6) s.branches.push_back(std::move(b));
    s.elseBody = std::move($7);
    $$ = makeStmt(std::move(s), @1); }
| MACRO IDENT block_body { $$ = makeStmt(MacroStmt{std::move($2), std::move($3)}, @1); }
| MACRO STRING block_body { $$ = makeStmt(MacroStmt{std::move($2), std::move($3)}, @1); }
| CALL expr ';' { $$ = makeStmt(CallStmt{std::move($2)}, @1); }
| DEFINECONSTANT '[' constants ']' ';' {
    $$ = makeStmt(DefineConstantStmt{std::move($3)}, @1); }
| PLUGIN '(' IDENT ')' '.' IDENT ';' {
    $$ = makeStmt(PluginStmt{std::move($3), std::move($6), nullptr}, @1); }
| PLUGIN '(' IDENT ')' '.' IDENT '=' expr ';' {
    $$ = makeStmt(PluginStmt{std::move($3), std::move($6), std::move($8)}, @1); }
;

block_body: stmts RETURN { $$ = std::move($1); } ;

elseifs:
  %empty { }
| elseifs ELSEIF '(' expr ')' stmts {
    $$ = std::move($1); $$.push_back(IfStmt::Branch{std::move($4), std::move($6)}); }
;
else_part: %empty { } | ELSE stmts { $$ = std::move($2); } ;

constants: constant { $$.push_back(std::move($1)); }
         | constants ',' constant { $$ = std::move($1); $$.push_back(std::move($3)); }
         | constants constant { $$ = std::move($1); $$.push_back(std::move($2)); } ;
constant:
  name '=' expr { $$.name = std::move($1); $$.loc = at(@1); $$.value = std::move($3); }
| name '[' ']' '=' expr {
    $$.name = std::move($1); $$.loc = at(@1); $$.isList = true; $$.value = std::move($5); }
| name '=' '{' items ',' attributes '}' {
    $$.name = std::move($1); $$.loc = at(@1);
    $$.value = grammar::listOrSingle(std::move($4), @3); $$.attributes = std::move($6); }
| name '[' ']' '=' '{' items ',' attributes '}' {
    $$.name = std::move($1); $$.loc = at(@1); $$.isList = true;
    $$.value = grammar::listOrSingle(std::move($6), @5); $$.attributes = std::move($8); }
;
attributes: attribute { $$.push_back(std::move($1)); }
          | attributes ',' attribute { $$ = std::move($1); $$.push_back(std::move($3)); } ;
attribute:
  ATTR expr { $$.name = std::move($1); $$.loc = at(@1); $$.values.push_back(std::move($2)); }
| ATTR '{' pairs '}' {
    $$.name = std::move($1); $$.loc = at(@1);
    for (auto& p : $3) for (auto& v : p.values) $$.values.push_back(std::move(v)); }
;
pairs: pair { $$.push_back(std::move($1)); }
     | pairs ',' pair { $$ = std::move($1); $$.push_back(std::move($3)); } ;
pair: expr '=' expr { $$.values.push_back(std::move($1)); $$.values.push_back(std::move($3)); } ;

args_opt: %empty { } | args { $$ = std::move($1); } ;
args: expr { $$.push_back(std::move($1)); }
    | args ',' expr { $$ = std::move($1); $$.push_back(std::move($3)); } ;

items: item { $$.push_back(std::move($1)); }
     | items ',' item { $$ = std::move($1); $$.push_back(std::move($3)); } ;
item:
  expr { $$ = std::move($1); }
| expr ':' expr {
    $$ = makeExpr(ExprKind::Range, @1);
    $$->args.push_back(std::move($1)); $$->args.push_back(std::move($3)); }
| expr ':' expr ':' expr {
    $$ = makeExpr(ExprKind::Range, @1); $$->args.push_back(std::move($1));
    $$->args.push_back(std::move($3)); $$->args.push_back(std::move($5)); }
| expr DOTS expr {  // the old spelling of a range: {1 ... 3} is {1:3}
    $$ = makeExpr(ExprKind::Range, @1);
    $$->args.push_back(std::move($1)); $$->args.push_back(std::move($3)); }
| expr DOTS expr ':' expr {  // {1 ... 9 : 2} is {1:9:2}
    $$ = makeExpr(ExprKind::Range, @1); $$->args.push_back(std::move($1));
    $$->args.push_back(std::move($3)); $$->args.push_back(std::move($5)); }
| ':' { $$ = makeExpr(ExprKind::All, @1); }
;

expr:
  expr '?' expr ':' expr {
    $$ = makeExpr(ExprKind::Ternary, @2); $$->args.push_back(std::move($1));
    $$->args.push_back(std::move($3)); $$->args.push_back(std::move($5)); }
| expr OR expr { $$ = binary("||", std::move($1), std::move($3), @2); }
| expr AND expr { $$ = binary("&&", std::move($1), std::move($3), @2); }
| expr EQ expr { $$ = binary("==", std::move($1), std::move($3), @2); }
| expr NE expr { $$ = binary("!=", std::move($1), std::move($3), @2); }
| expr '<' expr { $$ = binary("<", std::move($1), std::move($3), @2); }
| expr '>' expr { $$ = binary(">", std::move($1), std::move($3), @2); }
| expr LE expr { $$ = binary("<=", std::move($1), std::move($3), @2); }
| expr GE expr { $$ = binary(">=", std::move($1), std::move($3), @2); }
| expr '+' expr { $$ = binary("+", std::move($1), std::move($3), @2); }
| expr '-' expr { $$ = binary("-", std::move($1), std::move($3), @2); }
| expr '*' expr { $$ = binary("*", std::move($1), std::move($3), @2); }
| expr '/' expr { $$ = binary("/", std::move($1), std::move($3), @2); }
| expr '%' expr { $$ = binary("%", std::move($1), std::move($3), @2); }
| expr '^' expr { $$ = binary("^", std::move($1), std::move($3), @2); }
| '-' expr %prec UNARY { $$ = unary("-", std::move($2), @1); }
| '+' expr %prec UNARY { $$ = unary("+", std::move($2), @1); }
| '!' expr { $$ = unary("!", std::move($2), @1); }
| name INCR {  // b = a++; the value before the increment
    auto variable = makeExpr(ExprKind::Variable, @1); variable->name = std::move($1);
    $$ = unary("post++", std::move(variable), @2); }
| name DECR {
    auto variable = makeExpr(ExprKind::Variable, @1); variable->name = std::move($1);
    $$ = unary("post--", std::move(variable), @2); }
| primary { $$ = std::move($1); }
;

primary:
  NUMBER { $$ = makeExpr(ExprKind::Number, @1); $$->number = $1; }
| STRING { $$ = makeExpr(ExprKind::String, @1); $$->text = std::move($1); }
| '(' expr ')' { $$ = std::move($2); }
| '(' expr ',' args ')' {  // (x, y, z): a list in parentheses, as Point(1) = (0, 1, 0);
    $$ = makeExpr(ExprKind::List, @1); $$->args.push_back(std::move($2));
    for (auto& arg : $4) $$->args.push_back(std::move(arg)); }
| name { $$ = makeExpr(ExprKind::Variable, @1); $$->name = std::move($1); }
| name '[' ']' { $$ = makeExpr(ExprKind::WholeList, @1); $$->name = std::move($1); }
| name '[' expr ']' { $$ = grammar::elementOrCall(std::move($1), std::move($3), @1); }
| name '[' expr ',' args ']' {
    if (!$1.suffixes.empty()) throw SyntaxError(at(@4), "unexpected ',' in a list index");
    $$ = makeExpr(ExprKind::Call, @1); $$->text = std::move($1.base);
    $$->args.push_back(std::move($3));
    for (auto& arg : $5) $$->args.push_back(std::move(arg)); }
| IDENT '(' args_opt ')' {
    $$ = makeExpr(ExprKind::Call, @1); $$->text = std::move($1); $$->args = std::move($3); }
| '#' primary { $$ = makeExpr(ExprKind::Count, @1); $$->args.push_back(std::move($2)); }
| '{' '}' { $$ = makeExpr(ExprKind::List, @1); }
| '{' items '}' { $$ = makeExpr(ExprKind::List, @1); $$->args = std::move($2); }
| option_path { $$ = std::move($1); }
| struct_def { $$ = std::move($1); }
| IDENT SCOPE name {
    $$ = makeExpr(ExprKind::Member, @1); $$->words.push_back(std::move($1));
    $$->name = std::move($3); }
| IDENT SCOPE name '[' expr ']' {
    $$ = grammar::structByString(std::move($3), std::move($1), std::move($5), @1); }
| name '[' IDENT SCOPE '#' primary ']' {
    $$ = grammar::indexInNamespace(std::move($1), std::move($3), std::move($6), @1); }
| IDENT '(' IDENT SCOPE '#' primary ')' {
    ast::Name function; function.base = std::move($1);
    $$ = grammar::indexInNamespace(std::move(function), std::move($3), std::move($6), @1); }
| member_ref { $$ = std::move($1); }
| member_ref '(' ')' { $$ = std::move($1); $$->kind = ExprKind::MemberList; }
| member_ref '[' ']' { $$ = std::move($1); $$->kind = ExprKind::MemberList; }
| member_ref '(' expr ')' {
    $$ = std::move($1); $$->kind = ExprKind::MemberItem; $$->args.push_back(std::move($3)); }
| member_ref '[' expr ']' {
    $$ = std::move($1); $$->kind = ExprKind::MemberItem; $$->args.push_back(std::move($3)); }
| shape { $$ = std::move($1); }
| shape USINGWIRE part {
    // out[] = Extrude{ Surface{1}; } Using Wire{2}; the wire's braces become the last part.
    $$ = std::move($1); $$->words.push_back("Using Wire"); $$->parts.push_back(std::move($3)); }
| INTERSECT shape shape {  // Intersect Curve{1} Surface{2}: words Intersect Curve Surface
    $$ = std::move($2); $$->words.insert($$->words.begin(), "Intersect"); $$->loc = at(@1);
    for (auto& word : $3->words) $$->words.push_back(word);
    for (auto& part : $3->parts) $$->parts.push_back(std::move(part)); }
| words STRING {  // Surface "*": every surface, as Surface{:}
    $$ = makeExpr(ExprKind::Shape, @1); $$->words = std::move($1); $$->text = std::move($2);
    $$->parts.emplace_back(); $$->parts.back().items.push_back(makeExpr(ExprKind::All, @2)); }
| words '(' args_opt ')' {
    $$ = makeExpr(ExprKind::Shape, @1); $$->words = std::move($1);
    $$->parts.emplace_back(); $$->parts.back().items = std::move($3); }
| words IN shape {
    $$ = std::move($3); $1.push_back("In");
    $1.insert($1.end(), $$->words.begin(), $$->words.end()); $$->words = std::move($1); }
| DEFINENUMBER '[' expr ']' {
    $$ = makeExpr(ExprKind::DefineNumber, @1); $$->args.push_back(std::move($3)); }
| DEFINENUMBER '[' expr ',' attributes ']' {
    $$ = makeExpr(ExprKind::DefineNumber, @1); $$->args.push_back(std::move($3));
    $$->attributes = std::move($5); }
| DEFINESTRING '[' expr ']' {
    $$ = makeExpr(ExprKind::DefineString, @1); $$->args.push_back(std::move($3)); }
| DEFINESTRING '[' expr ',' attributes ']' {
    $$ = makeExpr(ExprKind::DefineString, @1); $$->args.push_back(std::move($3));
    $$->attributes = std::move($5); }
;

%%

namespace geomesh {

void Parser::error(const location_type& where, const std::string& message) {
  throw SyntaxError(grammar::at(where), message);
}

void Parser::report_syntax_error(const context& ctx) const {
  grammar::reportSyntaxError(lexer, ctx);
}

}  // namespace geomesh
