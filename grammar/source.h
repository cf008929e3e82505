// SourceLocation, SourceFile and SyntaxError: where in a script, its text, and what is wrong.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace geomesh {

// A place in a script: file name as given, 1-based line and column (a tab counts as one
// column, like any other byte).
struct SourceLocation {
  std::string file;
  int line = 1;
  int column = 1;
  friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

// The text of one script, kept so diagnostics can quote the offending line.
struct SourceFile {
  std::string name;
  std::string text;

  // Line `line` (1-based) without its end-of-line characters; empty when out of range.
  std::string_view lineText(int line) const;
};

// A lexical or syntax error: where it is and what is wrong, without any formatting. The
// interpreter turns it into a full diagnostic.
class SyntaxError : public std::runtime_error {
 public:
  SyntaxError(SourceLocation where, const std::string& message)
      : std::runtime_error(message), location_(std::move(where)) {}
  const SourceLocation& location() const { return location_; }

 private:
  SourceLocation location_;
};

}  // namespace geomesh
