// Located diagnostics: the text of an error or warning at a place in a script.
#include "grammar/diagnostic.h"

namespace geomesh {

namespace {

std::string caretLine(std::string_view sourceLine, int column) {
  std::string caret;
  for (int i = 0; i + 1 < column; ++i) {
    auto index = static_cast<std::size_t>(i);
    caret += index < sourceLine.size() && sourceLine[index] == '\t' ? '\t' : ' ';
  }
  caret += '^';
  return caret;
}

std::string prefix(const SourceLocation& where) {
  return where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
}

}  // namespace

std::string formatDiagnostic(const SourceLocation& where, std::string_view severity,
                             std::string_view message, std::string_view sourceLine) {
  std::string text = prefix(where);
  text.append(": ").append(severity).append(": ").append(message);
  text += '\n';
  text.append(sourceLine);
  text += '\n';
  text += caretLine(sourceLine, where.column);
  return text;
}

ScriptError::ScriptError(SourceLocation where, std::string message, std::string_view sourceLine)
    : std::runtime_error(message),
      location_(std::move(where)),
      message_(std::move(message)),
      text_(formatDiagnostic(location_, "error", message_, sourceLine)) {}

void ScriptError::addIncludedFrom(const SourceLocation& include) {
  text_ += "\n  included from " + prefix(include);
}

}  // namespace geomesh
