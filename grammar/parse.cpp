// parseScript: runs the Bison parser over the re2c lexer to build a script's syntax tree.
#include "grammar/parse.h"

#include "grammar/tokenizer.h"

namespace geomesh {

ast::StmtList parseScript(const std::string& fileName, std::string_view text) {
  Lexer lexer(fileName, text);
  ast::StmtList program;
  Parser parser(lexer, program);
  parser.parse();
  return program;
}

}  // namespace geomesh
