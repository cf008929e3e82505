// The statement table and the function registry: every command keyword and every built-in
// function has its row, and every row is reachable from a script.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <string_view>

#include "grammar/keywords.h"
#include "interpreter/function_registry.h"
#include "interpreter/script_interpreter.h"
#include "script_runner.h"

namespace geomesh::testing {
namespace {

bool contains(std::span<const std::string_view> words, std::string_view word) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

std::string_view headOf(std::string_view pattern) { return pattern.substr(0, pattern.find(' ')); }

// A call of `name` with `count` arguments, each the number 1.
std::string callWith(std::string_view name, std::size_t count, char open = '(', char close = ')') {
  std::string call = std::string(name) + open;
  for (std::size_t i = 0; i < count; ++i) call += i == 0 ? "1" : ", 1";
  return call + close;
}

TEST(StatementTable, EveryCommandKeywordStartsARowOrIsDeclaredToStartNone) {
  const std::vector<std::string_view> patterns = Interpreter::statementPatterns();
  const auto none = Interpreter::keywordsStartingNoStatement();
  for (std::string_view keyword : commandWords()) {
    const bool starts = std::any_of(patterns.begin(), patterns.end(), [&](std::string_view p) {
      return headOf(p) == keyword;
    });
    EXPECT_NE(starts, contains(none, keyword))
        << "'" << keyword << "' must either start a row of the statement table or be listed "
        << "among the keywords that start no statement (not both)";
  }
  for (std::string_view word : none)
    EXPECT_TRUE(contains(commandWords(), word)) << "'" << word << "' is no command keyword";
}

// A row whose words the lexer does not read as keywords could never be reached.
TEST(StatementTable, EveryRowIsMadeOfKeywords) {
  const std::vector<std::string_view> patterns = Interpreter::statementPatterns();
  for (std::size_t i = 0; i < patterns.size(); ++i) {
    std::string_view rest = patterns[i];
    if (i > 0) {
      EXPECT_LT(patterns[i - 1], rest) << "rows must be sorted and unique";
    }
    if (rest == "Struct") continue;  // the parser makes Struct definitions commands
    while (!rest.empty()) {
      const std::string_view word = headOf(rest);
      rest.remove_prefix(std::min(rest.size(), word.size() + 1));
      if (word == "...") {
        EXPECT_TRUE(rest.empty()) << patterns[i];
        continue;
      }
      EXPECT_TRUE(contains(commandWords(), word)) << "'" << word << "' in row '" << patterns[i]
                                                  << "' is no command keyword";
    }
  }
}

TEST(StatementTable, RowsMatchTheWholeCommandUnlessTheyTakeAnyWords) {
  ScriptRun run;
  // "Printf" is a row of its own: more words make another statement, which no row knows.
  run.run("Printf Mesh(\"x\");\nSleep 1;\nSleep Mesh 2;\nDraw;\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_EQ(run.log.warnings[0],
            "test.geo:1:1: warning: 'Printf Mesh' is not supported yet; ignored");
  EXPECT_EQ(run.out.str(), "");
}

TEST(StatementTable, KeywordsThatStartNoStatementWarnAsUnsupported) {
  ScriptRun run;
  run.run("Layers{1};\nLoop(2) = {1};\n");
  ASSERT_EQ(run.log.warnings.size(), 2u);
  EXPECT_EQ(run.log.warnings[0], "test.geo:1:1: warning: 'Layers' is not supported yet; ignored");
  EXPECT_EQ(run.log.warnings[1], "test.geo:2:1: warning: 'Loop' is not supported yet; ignored");
}

// A form its handler does not carry out is reported as the statement it is.
TEST(StatementTable, UnsupportedFormsOfKnownStatementsWarn) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0};\nMesh;\nCurve(1) = {1};\nCoherence(1);\nDelete 3;\n"
          "Print;\nField(1) = 2;\n");
  ASSERT_EQ(run.log.warnings.size(), 5u);
  EXPECT_EQ(run.log.warnings[0], "test.geo:2:1: warning: 'Mesh' is not supported yet; ignored");
  EXPECT_EQ(run.log.warnings[1], "test.geo:3:1: warning: 'Curve' is not supported yet; ignored");
  EXPECT_EQ(run.log.warnings[2],
            "test.geo:4:1: warning: 'Coherence' is not supported yet; ignored");
  EXPECT_EQ(run.log.warnings[3], "test.geo:5:1: warning: 'Delete' is not supported yet; ignored");
  EXPECT_EQ(run.log.warnings[4], "test.geo:7:1: warning: 'Field' is not supported yet; ignored");
}

TEST(FunctionRegistry, NamesAreTheGrammarsFunctionNames) {
  const FunctionRegistry registry = Interpreter::builtinFunctions();
  const std::set<std::string> inRegistry(registry.names().begin(), registry.names().end());
  const std::set<std::string> inGrammar(functionNames().begin(), functionNames().end());
  EXPECT_EQ(inRegistry, inGrammar);
  EXPECT_EQ(inRegistry.size(), registry.all().size()) << "a name defined twice";
}

TEST(FunctionRegistry, FindsEveryRowByItsName) {
  const FunctionRegistry registry = Interpreter::builtinFunctions();
  for (const BuiltinFunction& function : registry.all()) {
    ASSERT_EQ(registry.find(function.name), &function) << function.name;
    EXPECT_NE(function.math == nullptr, function.script == nullptr) << function.name;
  }
  EXPECT_EQ(registry.find("Sig"), nullptr);
  EXPECT_EQ(registry.find("sin"), nullptr);
  EXPECT_EQ(registry.find(""), nullptr);
}

// Called with as many arguments as its row allows, each function runs or fails on its
// arguments, never as an unknown function; so does Name[..], Gmsh's other way to call it.
TEST(FunctionRegistry, EveryRowIsReachableFromAScript) {
  const FunctionRegistry registry = Interpreter::builtinFunctions();
  for (const BuiltinFunction& function : registry.all()) {
    const std::size_t count = function.minArgs();
    std::string error = errorOf("x = " + callWith(function.name, count) + ";");
    EXPECT_EQ(error.find("unknown function"), std::string::npos) << error;
    if (function.maxArgs() == 0) continue;
    error = errorOf("x = " + callWith(function.name, std::max<std::size_t>(count, 1), '[', ']') +
                    ";");
    EXPECT_EQ(error.find("unknown function"), std::string::npos) << error;
    EXPECT_EQ(error.find("undefined variable"), std::string::npos) << error;
  }
}

std::string expectedCountError(const BuiltinFunction& function, std::size_t given) {
  if (function.script) return wrongArgumentCount(*function.script, given);
  const std::size_t count = function.math->arguments;
  return "'" + std::string(function.name) + "' takes " + std::to_string(count) + " argument" +
         (count == 1 ? "" : "s") + ", not " + std::to_string(given);
}

// A call with one argument too many or too few is refused with the row's count.
TEST(FunctionRegistry, EveryRowChecksItsArgumentCount) {
  const FunctionRegistry registry = Interpreter::builtinFunctions();
  for (const BuiltinFunction& function : registry.all()) {
    std::vector<std::size_t> wrong;
    if (function.minArgs() > 0) wrong.push_back(function.minArgs() - 1);
    if (function.maxArgs() != ScriptFunction::kAnyCount) wrong.push_back(function.maxArgs() + 1);
    for (std::size_t given : wrong)
      EXPECT_EQ(firstLineOf("x = " + callWith(function.name, given) + ";"),
                "test.geo:1:5: error: " + expectedCountError(function, given));
  }
}

TEST(FunctionRegistry, CountErrorsKeepTheirWording) {
  EXPECT_EQ(firstLineOf("x = Sin(1, 2);"), "test.geo:1:5: error: 'Sin' takes 1 argument, not 2");
  EXPECT_EQ(firstLineOf("x = Hypot(1);"),
            "test.geo:1:5: error: 'Hypot' takes 2 arguments, not 1");
  EXPECT_EQ(firstLineOf("s = StrSub(\"a\");"),
            "test.geo:1:5: error: 'StrSub' takes 2 to 3 arguments, not 1");
  EXPECT_EQ(firstLineOf("n = StrLen(\"a\", \"b\");"),
            "test.geo:1:5: error: 'StrLen' takes 1 arguments, not 2");
  EXPECT_EQ(firstLineOf("n = Find({1});"), "test.geo:1:5: error: Find takes 2 lists");
  EXPECT_EQ(firstLineOf("n = GetNumber();"),
            "test.geo:1:5: error: GetNumber takes 1 or 2 arguments");
  EXPECT_EQ(firstLineOf("x[] = LinSpace(1, 2);"),
            "test.geo:1:7: error: 'LinSpace' takes 3 arguments");
}

// A numeric function counts its arguments once they are evaluated: an error in an argument
// comes first.
TEST(FunctionRegistry, NumericArgumentsAreEvaluatedBeforeTheyAreCounted) {
  EXPECT_EQ(firstLineOf("x = Sin(1, nope);"),
            "test.geo:1:12: error: undefined variable 'nope'");
  EXPECT_EQ(firstLineOf("x = StrLen(\"a\", nope);"),
            "test.geo:1:5: error: 'StrLen' takes 1 arguments, not 2");
}

}  // namespace
}  // namespace geomesh::testing
