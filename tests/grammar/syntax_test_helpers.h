// Parsing helpers the grammar tests share.
#pragma once
#include <string>
#include <string_view>

#include "grammar/parse.h"

namespace geomesh {

// The statements of `text`, parsed as the file "p.geo".
inline ast::StmtList parse(std::string_view text) { return parseScript("p.geo", text); }

// "line:col: message" of the syntax error in `text`, or "" if it parses.
inline std::string syntaxError(std::string_view text) {
  try {
    parse(text);
  } catch (const SyntaxError& error) {
    return std::to_string(error.location().line) + ":" + std::to_string(error.location().column) +
           ": " + error.what();
  }
  return "";
}

}  // namespace geomesh
