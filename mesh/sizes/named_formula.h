// Formulas over named variables (the plugins' x, y, z, v0, w0, Time...), compiled with the
// size fields' expression evaluator.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "mesh/views/plugins.h"

namespace geomesh {

// Compiles `text` with MathExpression, each name of `variables` standing for the value at
// its position in the span the result is called with. Throws MathExpressionError (a
// std::exception) when the text is not a formula.
post::CompiledFormula compileNamedFormula(const std::string& text,
                                          const std::vector<std::string>& variables);

}  // namespace geomesh
