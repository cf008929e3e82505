// Lexer: the re2c scanner's interface, with its tracking of unclosed brackets and blocks.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "grammar/parser.hpp"

namespace geomesh {

// Turns script text into tokens for the parser. Keywords are case-sensitive, as in Gmsh.
// Words that introduce commands (Point, Surface, Mesh, ...) are WORD tokens; the few that
// only follow a shape (In, Using, Left, ...) are TAILWORD tokens; any word right after a '.'
// is a plain identifier, so option names never collide with keywords.
class Lexer {
 public:
  Lexer(std::string fileName, std::string_view text);

  Parser::symbol_type next();

  // The token before the current lookahead, for "expected ';' after ..." messages.
  const std::string& previousText() const { return previousText_; }
  const Parser::location_type& previousLocation() const { return previousLocation_; }
  const std::string& currentText() const { return currentText_; }
  const std::string& fileName() const { return fileName_; }

  // A bracket or block (For, If, Macro) not closed yet, where it was opened.
  struct OpenToken {
    std::string text;
    Parser::location_type where;
  };
  // The innermost one, or null when everything is closed.
  const OpenToken* innermostOpen() const { return open_.empty() ? nullptr : &open_.back(); }

 private:
  Parser::symbol_type scan();
  Parser::symbol_type word(std::string text, const Parser::location_type& where);
  Parser::symbol_type number(const Parser::location_type& where);
  Parser::symbol_type quoted(const Parser::location_type& where);
  Parser::symbol_type punctuation(int token, const Parser::location_type& where);
  Parser::symbol_type opening(Parser::symbol_type symbol, std::string text);
  Parser::symbol_type closing(Parser::symbol_type symbol);
  void skipBlockComment(const Parser::location_type& where);
  bool nextNonSpaceIs(char c) const;
  bool followedByWord(std::string_view word);
  void countLines(const char* from, const char* to);
  Parser::location_type tokenLocation() const;
  [[noreturn]] void fail(const Parser::location_type& where, const std::string& message) const;

  std::string fileName_;
  std::string text_;  // owns a NUL-terminated copy of the script
  const char* cursor_;
  const char* limit_;
  const char* token_ = nullptr;
  const char* lineStart_;
  int line_ = 1;
  bool afterDot_ = false;
  bool defineAhead_ = false;
  int defineDepth_ = 0;
  std::vector<OpenToken> open_;  // open brackets and blocks, innermost last
  std::string currentText_, previousText_;
  Parser::location_type currentLocation_, previousLocation_;
};

}  // namespace geomesh
