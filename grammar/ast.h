// The syntax tree of a .geo script: expressions, assignments, commands, loops, macros.
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "grammar/source.h"

namespace geomesh::ast {

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;
using ExprList = std::vector<ExprPtr>;

struct Stmt;
using StmtPtr = std::unique_ptr<Stmt>;
using StmtList = std::vector<StmtPtr>;

// A variable name, possibly built at run time: `a~{i}~{j}` names "a_<i>_<j>".
struct Name {
  std::string base;
  ExprList suffixes;
};

enum class ExprKind {
  Number,        // number
  String,        // text
  Variable,      // name
  Element,       // name[args[0]] (or the old name(args[0]) when name is no function)
  WholeList,     // name[] or name()
  Count,         // #args[0]: number of items of a list
  Unary,         // text is the operator ("-", "+", "!", "post++", "post--"); args[0]
  Binary,        // text is the operator; args[0] op args[1]
  Ternary,       // args[0] ? args[1] : args[2]
  Call,          // text(args...): a built-in function
  List,          // {args...}; items may be Range or All
  Range,         // args[0] : args[1] [: args[2]]
  All,           // ':' alone in an entity list, as in Surface{:}
  Option,        // text is the path "Mesh.MeshSizeMin"; args[0] is an index (Field[1].X)
  Shape,         // words{...}{...}: Point{1}, Boundary{ Surface{1}; }, Extrude{..}{..}
  DefineNumber,  // DefineNumber[args[0], attributes]
  DefineString,  // DefineString[args[0], attributes]
  StructDef,     // Struct words[0]::name (text "Append" or empty) [attributes]; its tag
  Member,        // words[0]::name.text: a Struct member (text empty: the Struct's tag)
  MemberItem,    // words[0]::name.text(args[0]): one item of a list member
  MemberList,    // words[0]::name.text(): a whole list member
};

// One brace group after a shape's words: either expressions `{1, 2:4}` or a block of
// shape items `{ Surface{1}; Recombine; }`.
struct ShapePart {
  bool isBlock = false;
  ExprList items;
};

// `Name "x"`, `Min 0`, `Choices{0, 1}` in DefineConstant / DefineNumber; also the members
// of a Struct (`epsr 5`, `Enum`: values empty when none is given).
struct Attribute {
  std::string name;
  SourceLocation loc;
  ExprList values;
};

struct Expr {
  ExprKind kind = ExprKind::Number;
  SourceLocation loc;
  int depth = 1;  // operators nested in this expression (bounded by the parser)
  double number = 0;
  std::string text;
  Name name;
  ExprList args;
  std::vector<std::string> words;   // Shape; the namespace of a Struct ("" for the global one)
  std::vector<ShapePart> parts;     // Shape
  std::vector<Attribute> attributes;  // DefineNumber / DefineString / StructDef
};

// Where an assignment stores its value.
struct LValue {
  enum class Form { Scalar, List, Element };
  Form form = Form::Scalar;
  bool parenthesized = false;  // the old a() / a(i) syntax
  Name name;
  ExprPtr index;  // Element
};

// a = e; a[] += e; a[i] = e; a++;   op is one of = += -= *= /= ++ --
struct AssignStmt {
  LValue target;
  std::string op;
  ExprPtr value;  // null for ++ and --
};

// Mesh.MeshSizeMin = e; Field[1].PointsList = {..};
struct OptionAssignStmt {
  std::string path;
  ExprPtr index;
  std::string op;
  ExprPtr value;
};

// A word after a shape command, with the value that follows it if any.
struct TailItem {
  std::string word;
  ExprPtr value;
};

// Any statement introduced by keywords: Point(1) = {...}; Plane Surface(1) = {...};
// Printf("..", x) > "f"; Mesh 2; Include "f"; Coherence; Recombine Surface{1};
// Translate{1,0,0}{ Point{1}; } Transfinite Curve{1} = 10 Using Progression 2;
// One record of a view in the parsed format: ST(coordinates){values}; or TIME{values};
// (`coordinates` empty, `hasCoordinates` false).
struct ViewItem {
  std::string type;
  bool hasCoordinates = false;
  ExprList coordinates;
  ExprList values;
  SourceLocation loc;
};

struct CommandStmt {
  enum class Args { None, Paren, Bracket, Bare };
  std::vector<std::string> words;
  Args argStyle = Args::None;
  ExprList args;
  ExprPtr shape;                 // when the command is a shape: words{..}{..}
  std::string op;                // "=", "+=", "-=" or empty
  ExprPtr value;                 // right-hand side
  std::vector<TailItem> tail;    // Using Progression 2 / In Surface{1} / Left ...
  std::string redirect;          // ">" or ">>" (Printf)
  ExprPtr redirectTarget;
  std::string colorName;         // Color Red{...}
  std::vector<ViewItem> viewItems;  // View "name" { ST(..){..}; ... };
};

struct ForStmt {
  Name variable;  // empty base for For (a:b:c)
  ExprPtr range;  // a list expression
  StmtList body;
};

struct IfStmt {
  struct Branch {
    ExprPtr condition;
    StmtList body;
  };
  std::vector<Branch> branches;
  StmtList elseBody;
};

// Macro Name ... Return  (also "Function")
struct MacroStmt {
  std::string name;
  StmtList body;
};

// Call Name; Call "name"; Call StrCat(..);
struct CallStmt {
  ExprPtr name;
};

// DefineConstant[ a = 1, b = {2, Name "x", Min 0}, c = "s" ];
struct ConstantDef {
  Name name;
  SourceLocation loc;
  bool isList = false;
  ExprPtr value;
  std::vector<Attribute> attributes;
};
struct DefineConstantStmt {
  std::vector<ConstantDef> constants;
};

// Plugin(Name).Option = e;  Plugin(Name).Run;
struct PluginStmt {
  std::string plugin;
  std::string member;
  ExprPtr value;
};

struct EmptyStmt {};

struct Stmt {
  SourceLocation loc;
  std::variant<EmptyStmt, AssignStmt, OptionAssignStmt, CommandStmt, ForStmt, IfStmt, MacroStmt,
               CallStmt, DefineConstantStmt, PluginStmt>
      node;
};

}  // namespace geomesh::ast
