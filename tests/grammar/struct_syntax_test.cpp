// Struct definitions and member access, and Name[...] calls of built-in functions.
#include <gtest/gtest.h>

#include "grammar/parse.h"
#include "tests/grammar/syntax_test_helpers.h"

namespace geomesh {
namespace {

using namespace ast;

const Expr& assignedValue(const StmtList& program, std::size_t i = 0) {
  return *std::get<AssignStmt>(program.at(i)->node).value;
}

TEST(StructSyntax, DefinitionWithNamespaceAppendAndMembers) {
  auto program =
      parse("Struct NS::Mat (Append) [ Tag 3, epsr 5, mu {1, 2}, label \"iron\", Enum, A ];");
  ASSERT_EQ(program.size(), 1u);
  const auto& command = std::get<CommandStmt>(program[0]->node);
  ASSERT_EQ(command.words, std::vector<std::string>{"Struct"});
  const Expr& definition = *command.args.at(0);
  EXPECT_EQ(definition.kind, ExprKind::StructDef);
  EXPECT_EQ(definition.words, std::vector<std::string>{"NS"});
  EXPECT_EQ(definition.name.base, "Mat");
  EXPECT_EQ(definition.text, "Append");
  ASSERT_EQ(definition.attributes.size(), 6u);
  EXPECT_EQ(definition.attributes[0].name, "Tag");
  EXPECT_EQ(definition.attributes[2].values.at(0)->kind, ExprKind::List);
  EXPECT_EQ(definition.attributes[3].values.at(0)->kind, ExprKind::String);
  EXPECT_TRUE(definition.attributes[4].values.empty());
  EXPECT_EQ(definition.attributes[5].name, "A");
}

TEST(StructSyntax, EmptyDefinitionAndDefinitionAsAValue) {
  EXPECT_EQ(syntaxError("Struct Empty [ ];"), "");
  auto program = parse("t = Struct S~{2} [ Type 3 ];");
  const Expr& value = assignedValue(program);
  EXPECT_EQ(value.kind, ExprKind::StructDef);
  EXPECT_EQ(value.words, std::vector<std::string>{""});
  EXPECT_EQ(value.name.suffixes.size(), 1u);
}

TEST(StructSyntax, MemberReads) {
  auto program = parse(
      "a = M.x; b = NS::M.x; c = M.l(1); d() = M.l(); e = #M.l(); f = M.l[0]; g = NS::M;");
  EXPECT_EQ(assignedValue(program, 0).kind, ExprKind::Member);
  EXPECT_EQ(assignedValue(program, 0).text, "x");
  EXPECT_EQ(assignedValue(program, 1).words, std::vector<std::string>{"NS"});
  EXPECT_EQ(assignedValue(program, 2).kind, ExprKind::MemberItem);
  EXPECT_EQ(assignedValue(program, 3).kind, ExprKind::MemberList);
  EXPECT_EQ(assignedValue(program, 4).kind, ExprKind::Count);
  EXPECT_EQ(assignedValue(program, 5).kind, ExprKind::MemberItem);
  EXPECT_EQ(assignedValue(program, 6).kind, ExprKind::Member);
  EXPECT_TRUE(assignedValue(program, 6).text.empty());
}

TEST(StructSyntax, StructsNamedByStringsAndByIndex) {
  auto program = parse("a = NS::S2N[s].Type; b = NameStruct[NS::#2]; c = NameStruct(#1);");
  const Expr& byString = assignedValue(program, 0);
  EXPECT_EQ(byString.kind, ExprKind::Member);
  EXPECT_TRUE(byString.name.base.empty());
  EXPECT_EQ(byString.name.suffixes.size(), 1u);
  const Expr& byIndex = assignedValue(program, 1);
  ASSERT_EQ(byIndex.kind, ExprKind::Call);
  EXPECT_EQ(byIndex.args.at(0)->words, std::vector<std::string>{"NS"});
  EXPECT_EQ(assignedValue(program, 2).args.at(0)->kind, ExprKind::Count);
  EXPECT_EQ(syntaxError("a = Foo[s].Type;"),
            "1:5: expected S2N[...] before '.' to name a Struct by a string");
}

TEST(StructSyntax, MisspelledAppendAndTrailingComma) {
  EXPECT_EQ(syntaxError("Struct M (Apend) [ x 1 ];"),
            "1:11: expected '(Append)' after the Struct name");
  EXPECT_NE(syntaxError("Struct M [ x 1, ];"), "");
  EXPECT_NE(syntaxError("Struct M;"), "");
}

TEST(StructSyntax, MemberAssignmentParses) {
  auto program = parse("M.x = 3;");
  const auto& command = std::get<CommandStmt>(program.at(0)->node);
  EXPECT_EQ(command.op, "=");
  EXPECT_EQ(command.args.at(0)->text, "x");
}

// Built-in functions take brackets as well as parentheses: Str[...], StrCat[a, b].
TEST(StructSyntax, BracketCallsOfBuiltInFunctions) {
  auto program = parse("a = Str[{\"x\"}]; b = StrCat[\"a\", \"b\"]; c = list[2];");
  EXPECT_EQ(assignedValue(program, 0).kind, ExprKind::Call);
  EXPECT_EQ(assignedValue(program, 0).text, "Str");
  EXPECT_EQ(assignedValue(program, 1).kind, ExprKind::Call);
  EXPECT_EQ(assignedValue(program, 1).args.size(), 2u);
  EXPECT_EQ(assignedValue(program, 2).kind, ExprKind::Element);
}

}  // namespace
}  // namespace geomesh
