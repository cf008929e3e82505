// Located diagnostics: "file:line:col: error: message", the source line and a caret.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "grammar/source.h"

namespace geomesh {

// "file:line:col: <severity>: message", then the source line and a caret under the column
// (tabs of the source line kept, so the caret lines up in a terminal). `sourceLine` may be
// empty when the text is not available.
std::string formatDiagnostic(const SourceLocation& where, std::string_view severity,
                             std::string_view message, std::string_view sourceLine);

// An error at a place in a script: thrown by the interpreter, and by the library layer when a
// failure met later (meshing) goes back to the statement that caused it. what() is the
// complete diagnostic, ready to print as is.
class ScriptError : public std::runtime_error {
 public:
  ScriptError(SourceLocation where, std::string message, std::string_view sourceLine);

  const char* what() const noexcept override { return text_.c_str(); }
  const SourceLocation& location() const { return location_; }
  const std::string& message() const { return message_; }

  // Adds "  included from file:line:col" for each Include the error came through.
  void addIncludedFrom(const SourceLocation& include);

 private:
  SourceLocation location_;
  std::string message_;
  std::string text_;
};

}  // namespace geomesh
