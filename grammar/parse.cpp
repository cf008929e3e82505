// parseScript: runs the Bison parser over the re2c lexer to build a script's syntax tree.
#include "grammar/parse.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <vector>

#include "grammar/tokenizer.h"

namespace geomesh {

namespace {

ast::StmtList parseText(const std::string& fileName, std::string_view text) {
  Lexer lexer(fileName, text);
  ast::StmtList program;
  Parser parser(lexer, program);
  parser.parse();
  return program;
}

// The text between If (cond) / ElseIf (cond) / Else and the keyword that ends the branch.
struct Branch {
  std::size_t begin = 0, end = 0;
};

bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Just after the parenthesis that closes the one opening at or after `at` (string and
// comment free text assumed between them); npos when there is none.
std::size_t afterParentheses(std::string_view text, std::size_t at) {
  while (at < text.size() && text[at] != '(') {
    if (!std::isspace(static_cast<unsigned char>(text[at]))) return std::string_view::npos;
    ++at;
  }
  int depth = 0;
  for (; at < text.size(); ++at) {
    if (text[at] == '(') ++depth;
    if (text[at] == ')' && --depth == 0) return at + 1;
  }
  return std::string_view::npos;
}

// Every branch of every If block of the script, and every Macro's body, found by their
// keywords outside comments and strings: the reference skips the branches it does not take,
// and the macros until they are called, without reading them.
std::vector<Branch> conditionalBranches(std::string_view text) {
  std::vector<Branch> branches;
  std::vector<std::size_t> open;    // per open If: the start of its current branch's body
  std::vector<std::size_t> macros;  // per open Macro: the start of its body
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      const std::size_t close = text.find("*/", i + 2);
      i = close == std::string_view::npos ? text.size() : close + 2;
    } else if (c == '"' || c == '\'') {
      for (++i; i < text.size() && text[i] != c; ++i)
        if (text[i] == '\\') ++i;
      ++i;
    } else if (isWordChar(c)) {
      const std::size_t start = i;
      while (i < text.size() && isWordChar(text[i])) ++i;
      if (start > 0 && (isWordChar(text[start - 1]) || text[start - 1] == '.')) continue;
      const std::string_view word = text.substr(start, i - start);
      if (word == "If" || word == "ElseIf") {
        if (word == "ElseIf" && !open.empty()) branches.push_back({open.back(), start});
        const std::size_t body = afterParentheses(text, i);
        if (body == std::string_view::npos) continue;
        if (word == "If") open.push_back(body);
        else if (!open.empty()) open.back() = body;
        i = body;
      } else if (word == "Else" && !open.empty()) {
        branches.push_back({open.back(), start});
        open.back() = i;
      } else if (word == "EndIf" && !open.empty()) {
        branches.push_back({open.back(), start});
        open.pop_back();
      } else if (word == "Macro" || word == "Function") {
        // The body starts on the line after the macro's name.
        const std::size_t line = text.find('\n', i);
        if (line != std::string_view::npos) macros.push_back(line + 1);
      } else if (word == "Return" && !macros.empty()) {
        branches.push_back({macros.back(), start});
        macros.pop_back();
      }
    } else {
      ++i;
    }
  }
  return branches;
}

std::size_t offsetOf(std::string_view text, const SourceLocation& where) {
  std::size_t offset = 0;
  for (int line = 1; line < where.line && offset < text.size(); ++offset)
    if (text[offset] == '\n') ++line;
  return offset + static_cast<std::size_t>(std::max(where.column - 1, 0));
}

// The branch body is blanked (its line breaks kept, so every other place keeps its line and
// column) and an Error statement carrying the syntax error is put where the error was: the
// script fails there, as before, if and only if it takes that branch.
std::string deferError(std::string text, const Branch& branch, std::size_t at,
                       const std::string& message) {
  for (std::size_t k = branch.begin; k < branch.end; ++k)
    if (text[k] != '\n') text[k] = ' ';
  std::string quoted;
  for (char c : message) {
    if (c == '"') quoted += '\\';
    quoted += c == '\n' ? ' ' : c;
  }
  text.insert(at, "Error(\"" + quoted + "\");");
  return text;
}

}  // namespace

ast::StmtList parseScript(const std::string& fileName, std::string_view text) {
  std::string patched(text);
  std::vector<std::size_t> deferredBranches;  // where the bodies blanked so far begin
  constexpr std::size_t kMaxDeferred = 64;
  while (true) {
    try {
      return parseText(fileName, patched);
    } catch (const SyntaxError& error) {
      const std::size_t at = offsetOf(patched, error.location());
      const Branch* innermost = nullptr;
      const std::vector<Branch> branches = conditionalBranches(patched);
      for (const Branch& b : branches)
        if (b.begin <= at && at <= b.end && (!innermost || b.begin >= innermost->begin))
          innermost = &b;
      // Outside any branch, or in one already deferred: the error stands.
      if (!innermost || at > patched.size() || deferredBranches.size() == kMaxDeferred ||
          std::find(deferredBranches.begin(), deferredBranches.end(), innermost->begin) !=
              deferredBranches.end())
        throw;
      deferredBranches.push_back(innermost->begin);
      patched = deferError(std::move(patched), *innermost, at, error.what());
    }
  }
}

}  // namespace geomesh
