// Tests of the parser: statements, shapes, options, lists, control flow, error locations.
#include <gtest/gtest.h>

#include "grammar/parse.h"
#include "tests/grammar/syntax_test_helpers.h"

namespace geomesh {
namespace {

using namespace ast;

template <class Node>
const Node& only(const StmtList& program) {
  EXPECT_EQ(program.size(), 1u);
  return std::get<Node>(program.at(0)->node);
}

TEST(Parser, AssignmentWithPrecedence) {
  auto program = parse("a = 1 + 2 * -3 ^ 2;");
  const auto& assign = only<AssignStmt>(program);
  EXPECT_EQ(assign.target.name.base, "a");
  EXPECT_EQ(assign.op, "=");
  const Expr& sum = *assign.value;
  ASSERT_EQ(sum.kind, ExprKind::Binary);
  EXPECT_EQ(sum.text, "+");
  const Expr& product = *sum.args[1];
  EXPECT_EQ(product.text, "*");
  const Expr& negation = *product.args[1];
  ASSERT_EQ(negation.kind, ExprKind::Unary);
  EXPECT_EQ(negation.args[0]->text, "^");  // -(3^2)
}

TEST(Parser, LocationsOfStatementsAndExpressions) {
  auto program = parse("\n  x = 2;\n\ty = x;");
  ASSERT_EQ(program.size(), 2u);
  EXPECT_EQ(program[0]->loc, (SourceLocation{"p.geo", 2, 3}));
  EXPECT_EQ(program[1]->loc, (SourceLocation{"p.geo", 3, 2}));
  EXPECT_EQ(std::get<AssignStmt>(program[1]->node).value->loc, (SourceLocation{"p.geo", 3, 6}));
}

TEST(Parser, GeometryCommands) {
  auto program = parse("Plane Surface(1) = {1, -2};");
  const auto& command = only<CommandStmt>(program);
  EXPECT_EQ(command.words, (std::vector<std::string>{"Plane", "Surface"}));
  EXPECT_EQ(command.argStyle, CommandStmt::Args::Paren);
  EXPECT_EQ(command.op, "=");
  ASSERT_EQ(command.value->kind, ExprKind::List);
  EXPECT_EQ(command.value->args.size(), 2u);
}

TEST(Parser, PhysicalWithNameAndTag) {
  auto program = parse("Physical Surface(\"wall\", 5) = {1:3};");
  const auto& command = only<CommandStmt>(program);
  ASSERT_EQ(command.args.size(), 2u);
  EXPECT_EQ(command.args[0]->kind, ExprKind::String);
  EXPECT_EQ(command.value->args[0]->kind, ExprKind::Range);
}

TEST(Parser, ShapesWithBlocksAndTails) {
  auto program = parse(
      "Extrude {0, 0, 1} { Surface{1}; Layers{10}; Recombine; }\n"
      "Transfinite Curve{1, 2} = 10 Using Progression 1.2;\n"
      "Point{5} In Surface{1};\n"
      "Periodic Surface{2} = {1} Translate{1, 0, 0};\n");
  ASSERT_EQ(program.size(), 4u);
  const auto& extrude = std::get<CommandStmt>(program[0]->node);
  ASSERT_EQ(extrude.shape->parts.size(), 2u);
  EXPECT_FALSE(extrude.shape->parts[0].isBlock);
  EXPECT_TRUE(extrude.shape->parts[1].isBlock);
  EXPECT_EQ(extrude.shape->parts[1].items.size(), 3u);
  const auto& transfinite = std::get<CommandStmt>(program[1]->node);
  EXPECT_EQ(transfinite.words, (std::vector<std::string>{"Transfinite", "Curve"}));
  ASSERT_EQ(transfinite.tail.size(), 2u);
  EXPECT_EQ(transfinite.tail[0].word, "Using");
  EXPECT_EQ(transfinite.tail[1].word, "Progression");
  EXPECT_EQ(transfinite.tail[1].value->number, 1.2);
  EXPECT_EQ(std::get<CommandStmt>(program[2]->node).tail[0].word, "In");
  EXPECT_EQ(std::get<CommandStmt>(program[3]->node).tail[0].value->words[0], "Translate");
}

TEST(Parser, OptionsAndFields) {
  auto program = parse("Mesh.Color.Points = {1,2,3}; Field[1].PointsList = {1}; Field[2] = Box;");
  ASSERT_EQ(program.size(), 3u);
  EXPECT_EQ(std::get<OptionAssignStmt>(program[0]->node).path, "Mesh.Color.Points");
  const auto& field = std::get<OptionAssignStmt>(program[1]->node);
  EXPECT_EQ(field.path, "Field.PointsList");
  EXPECT_NE(field.index, nullptr);
  EXPECT_EQ(std::get<CommandStmt>(program[2]->node).value->text, "Box");
}

TEST(Parser, ListsRangesAndIndexing) {
  auto program = parse("a[] = {1:10:2, b[], c[{0, 1}], #d[], e~{i}};");
  const auto& assign = only<AssignStmt>(program);
  EXPECT_EQ(assign.target.form, LValue::Form::List);
  const auto& items = assign.value->args;
  ASSERT_EQ(items.size(), 5u);
  EXPECT_EQ(items[0]->kind, ExprKind::Range);
  EXPECT_EQ(items[0]->args.size(), 3u);
  EXPECT_EQ(items[1]->kind, ExprKind::WholeList);
  EXPECT_EQ(items[2]->kind, ExprKind::Element);
  EXPECT_EQ(items[3]->kind, ExprKind::Count);
  EXPECT_EQ(items[4]->name.suffixes.size(), 1u);
}

TEST(Parser, ControlFlow) {
  auto program = parse(
      "For i In {1:3}\n  If (i == 2)\n    a = 1;\n  ElseIf (i == 3)\n    a = 2;\n  Else\n"
      "    a = 3;\n  EndIf\nEndFor\nFor (1:2) EndFor\nMacro M\n  b = 1;\nReturn\nCall M;");
  ASSERT_EQ(program.size(), 4u);
  const auto& loop = std::get<ForStmt>(program[0]->node);
  EXPECT_EQ(loop.variable.base, "i");
  const auto& branches = std::get<IfStmt>(loop.body.at(0)->node);
  EXPECT_EQ(branches.branches.size(), 2u);
  EXPECT_EQ(branches.elseBody.size(), 1u);
  EXPECT_TRUE(std::get<ForStmt>(program[1]->node).variable.base.empty());
  EXPECT_EQ(std::get<MacroStmt>(program[2]->node).name, "M");
}

TEST(Parser, DefineConstantWithAndWithoutCommas) {
  auto program = parse(
      "DefineConstant[ a = 1, b = {2, Min 0, Max 10, Name \"P/b\"}\n"
      "  c = {0, Choices{0=\"x\", 1=\"y\"}} s = \"str\" ];");
  const auto& define = only<DefineConstantStmt>(program);
  ASSERT_EQ(define.constants.size(), 4u);
  EXPECT_EQ(define.constants[1].attributes.size(), 3u);
  EXPECT_EQ(define.constants[1].value->number, 2);
  EXPECT_EQ(define.constants[2].attributes[0].values.size(), 4u);
}

// Attribute names that are also keywords (Macro) are attributes inside DefineConstant.
TEST(Parser, KeywordsAsDefineConstantAttributes) {
  auto program = parse(
      "DefineConstant[ m = {\"t.script\", Name \"Macros/Title\", Macro \"Gmsh\", AutoCheck 0},\n"
      "  h = {1, ShortHelp \"h\"} ];\nMacro M\nReturn\n");
  ASSERT_EQ(program.size(), 2u);
  const auto& define = std::get<DefineConstantStmt>(program[0]->node);
  ASSERT_EQ(define.constants.size(), 2u);
  EXPECT_EQ(define.constants[0].attributes[1].name, "Macro");
  EXPECT_EQ(define.constants[1].attributes[0].name, "ShortHelp");
  EXPECT_EQ(std::get<MacroStmt>(program[1]->node).name, "M");
}

TEST(Parser, MissingSemicolonPointsAfterThePreviousToken) {
  EXPECT_EQ(syntaxError("a = 1\nb = 2;"), "1:6: expected ';' after '1' (found 'b')");
  EXPECT_EQ(syntaxError("Point(1) = {0, 0, 0}"),
            "1:21: expected ';' after '}' (found end of file)");
}

TEST(Parser, UnexpectedTokenNamesWhatWasExpected) {
  EXPECT_EQ(syntaxError("a = (1 + 2;"), "1:11: unexpected ';', expected ')' or ','");
  EXPECT_EQ(syntaxError("a = * 2;"), "1:5: unexpected '*', expected an expression");
}

TEST(Parser, EndOfFileInsideABlockOrBracketPointsAtItsOpening) {
  EXPECT_EQ(syntaxError("For i In {1:2}\n a = 1;\n"),
            "1:1: 'For' is never closed: 'EndFor' expected before the end of the file");
  EXPECT_EQ(syntaxError("a = 1;\nIf (a)\n  For i In {1:2}\n  EndFor\n"),
            "2:1: 'If' is never closed: 'EndIf' expected before the end of the file");
  EXPECT_EQ(syntaxError("Macro m\n a = 1;\n"),
            "1:1: 'Macro' is never closed: 'Return' expected before the end of the file");
  EXPECT_EQ(syntaxError("x = 1;\nLine(1) = {1, 2\n"),
            "2:11: '{' is never closed: '}' expected before the end of the file");
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST(ParserLimits, DeepNestingIsASyntaxErrorNotACrash) {
  std::string deep = "a = " + std::string(100000, '(') + "1" + std::string(100000, ')') + ";";
  EXPECT_EQ(syntaxError(deep), "1:261: nesting deeper than 256 levels");
  std::string sum = "a = 1";
  for (int i = 0; i < 5000; ++i) sum += "+1";
  EXPECT_EQ(syntaxError(sum + ";").substr(0, 40), "1:4004: expression too deeply nested (mo");
  std::string loops;
  for (int i = 0; i < 300; ++i) loops += "For (1:2)\n";
  EXPECT_EQ(syntaxError(loops), "256:5: nesting deeper than 256 levels");
}

TEST(ParserLimits, CommentMarkersInsideStringsAreText) {
  auto program = parse("s = \"a // b /* c\";");
  EXPECT_EQ(std::get<AssignStmt>(program.at(0)->node).value->text, "a // b /* c");
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST(Parser, ExtrudeUsingWireNeedsNoSemicolon) {
  auto program = parse("Extrude { Surface{1}; } Using Wire {2}\nDelete { Point{1}; }\n");
  ASSERT_EQ(program.size(), 2u);
  const auto& extrude = std::get<CommandStmt>(program[0]->node);
  ASSERT_EQ(extrude.tail.size(), 1u);
  EXPECT_EQ(extrude.tail[0].word, "Using");
  EXPECT_EQ(extrude.tail[0].value->words[0], "Wire");
}

}  // namespace
}  // namespace geomesh
