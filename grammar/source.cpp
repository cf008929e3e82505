// SourceFile::lineText: one line of a script, for diagnostics to quote.
#include "grammar/source.h"

namespace geomesh {

std::string_view SourceFile::lineText(int line) const {
  std::string_view rest = text;
  for (int current = 1; current < line; ++current) {
    auto newline = rest.find('\n');
    if (newline == std::string_view::npos) return {};
    rest.remove_prefix(newline + 1);
  }
  auto end = rest.find('\n');
  std::string_view result = rest.substr(0, end);
  if (!result.empty() && result.back() == '\r') result.remove_suffix(1);
  return result;
}

}  // namespace geomesh
