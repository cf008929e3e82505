// parseScript: a whole .geo script to its syntax tree, or a located SyntaxError.
#pragma once

#include <string>
#include <string_view>

#include "grammar/ast.h"

namespace geomesh {

// Parses a whole script. Throws SyntaxError with the exact place of the first error.
ast::StmtList parseScript(const std::string& fileName, std::string_view text);

}  // namespace geomesh
