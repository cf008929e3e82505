// Tests of the lexer: numbers, keywords, operators, strings, comments and lexical errors.
#include <gtest/gtest.h>

#include "grammar/tokenizer.h"

namespace geomesh {
namespace {

using Kind = Parser::symbol_kind_type;

// What a test needs of a token (symbol_type itself cannot be stored in a vector: its
// move constructor is not noexcept).
struct Token {
  Kind kind;
  double number = 0;
  std::string text;
  int line = 0, column = 0;
};

std::vector<Token> tokensOf(std::string_view text) {
  Lexer lexer("l.geo", text);
  std::vector<Token> tokens;
  for (;;) {
    Parser::symbol_type symbol = lexer.next();
    Token token{symbol.kind(), 0, "", symbol.location.begin.line, symbol.location.begin.column};
    if (symbol.kind() == Parser::symbol_kind::S_NUMBER) token.number = symbol.value.as<double>();
    if (symbol.kind() == Parser::symbol_kind::S_STRING) token.text = symbol.value.as<std::string>();
    tokens.push_back(token);
    if (token.kind == Parser::symbol_kind::S_YYEOF) break;
  }
  return tokens;
}

// Token names as the parser shows them in messages, without quotes: "keyword", "For", ".".
std::vector<std::string> kindsOf(std::string_view text) {
  std::vector<std::string> kinds;
  for (const auto& token : tokensOf(text)) {
    std::string name = Parser::symbol_name(token.kind);
    if (name.size() >= 2 && (name.front() == '"' || name.front() == '\''))
      name = name.substr(1, name.size() - 2);
    kinds.push_back(name);
  }
  return kinds;
}
using Names = std::vector<std::string>;

double numberOf(std::string_view text) {
  auto tokens = tokensOf(text);
  EXPECT_EQ(tokens.size(), 2u) << text;
  EXPECT_EQ(tokens[0].kind, Parser::symbol_kind::S_NUMBER) << text;
  return tokens[0].number;
}

TEST(Lexer, NumbersInEveryNotation) {
  EXPECT_DOUBLE_EQ(numberOf("42"), 42);
  EXPECT_DOUBLE_EQ(numberOf("3.25"), 3.25);
  EXPECT_DOUBLE_EQ(numberOf("1."), 1);
  EXPECT_DOUBLE_EQ(numberOf(".5"), 0.5);
  EXPECT_DOUBLE_EQ(numberOf("1e3"), 1000);
  EXPECT_DOUBLE_EQ(numberOf("1E-2"), 0.01);
  EXPECT_DOUBLE_EQ(numberOf("2.5e+2"), 250);
  EXPECT_DOUBLE_EQ(numberOf(".5e1"), 5);
  EXPECT_DOUBLE_EQ(numberOf("1d2"), 100);
  EXPECT_DOUBLE_EQ(numberOf("007"), 7);
}

TEST(Lexer, KeywordsIdentifiersAndOptionNames) {
  EXPECT_EQ(kindsOf("Point x For EndFor If"),
            (Names{"keyword", "identifier", "For", "EndFor", "If", "end of file"}));
  // After a dot every word is a plain name, even one that is a keyword elsewhere.
  EXPECT_EQ(kindsOf("Mesh.Point"), (Names{"keyword", ".", "identifier", "end of file"}));
  EXPECT_EQ(kindsOf("In Using Progression"), (Names{"In", "modifier", "modifier", "end of file"}));
}

TEST(Lexer, AttributesOnlyInsideDefineBrackets) {
  auto kinds = kindsOf("Name DefineConstant[a = {1, Name \"x\", Min 0}] Min");
  EXPECT_EQ(kinds.front(), "identifier");
  EXPECT_EQ(std::count(kinds.begin(), kinds.end(), "attribute"), 2);
  EXPECT_EQ(kinds[kinds.size() - 2], "identifier");
  // Min(...) inside the brackets is still the function.
  auto call = kindsOf("DefineNumber[Min(1, 2)]");
  EXPECT_EQ(call[2], "identifier");
}

TEST(Lexer, MultiCharacterOperators) {
  EXPECT_EQ(kindsOf("== != <= >= && || ++ -- += -= *= /= >>"),
            (Names{"==", "!=", "<=", ">=", "&&", "||", "++", "--", "+=", "-=", "*=", "/=", ">>",
                   "end of file"}));
}

TEST(Lexer, StringsKeepTheirTextAndUnescapeQuotes) {
  auto tokens = tokensOf(R"("a\tb" "say \"hi\"")");
  EXPECT_EQ(tokens[0].text, "a\\tb");
  EXPECT_EQ(tokens[1].text, "say \"hi\"");
}

TEST(Lexer, CommentsAreSkippedAndLinesCounted) {
  auto tokens = tokensOf("// line comment\n/* block\n comment */ x /**/\n\ty");
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[0].line, 3);
  EXPECT_EQ(tokens[0].column, 13);
  EXPECT_EQ(tokens[1].line, 4);
  EXPECT_EQ(tokens[1].column, 2);
}

TEST(Lexer, UnterminatedBlockCommentIsAnErrorAtItsStart) {
  try {
    tokensOf("x = 1;\n  /* never closed\n\n");
    FAIL() << "no error";
  } catch (const SyntaxError& error) {
    EXPECT_EQ(error.location(), (SourceLocation{"l.geo", 2, 3}));
    EXPECT_STREQ(error.what(), "unterminated block comment");
  }
}

TEST(Lexer, UnterminatedStringAndStrayCharacters) {
  try {
    tokensOf("a = \"open");
    FAIL() << "no error";
  } catch (const SyntaxError& error) {
    EXPECT_EQ(error.location().column, 5);
    EXPECT_STREQ(error.what(), "unterminated string");
  }
  try {
    tokensOf("a = 1 $ 2;");
    FAIL() << "no error";
  } catch (const SyntaxError& error) {
    EXPECT_EQ(error.location().column, 7);
    EXPECT_STREQ(error.what(), "unexpected character '$'");
  }
}

}  // namespace
}  // namespace geomesh
