// Formulas over named variables: the names become the evaluator's F<n> placeholders.
#include "mesh/sizes/named_formula.h"

#include <cctype>
#include <memory>

#include "mesh/sizes/math_expression.h"

namespace geomesh {

namespace {

// `text` with every whole word that names a variable replaced by F<its position>.
std::string withPlaceholders(const std::string& text, const std::vector<std::string>& variables) {
  std::string renamed;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (!std::isalpha(c) && c != '_') {
      renamed += text[i++];
      continue;
    }
    std::size_t j = i;
    while (j < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_'))
      ++j;
    const std::string word = text.substr(i, j - i);
    std::string replacement = word;
    for (std::size_t k = 0; k < variables.size(); ++k)
      if (variables[k] == word) replacement = "F" + std::to_string(k);
    renamed += replacement;
    i = j;
  }
  return renamed;
}

}  // namespace

post::CompiledFormula compileNamedFormula(const std::string& text,
                                          const std::vector<std::string>& variables) {
  auto expression = std::make_shared<const MathExpression>(withPlaceholders(text, variables));
  return [expression](std::span<const double> values) {
    const std::vector<int>& used = expression->fieldsUsed();
    double picked[32];
    std::vector<double> many;
    std::span<double> fields;
    if (used.size() <= 32) {
      fields = std::span<double>(picked, used.size());
    } else {
      many.resize(used.size());
      fields = many;
    }
    for (std::size_t k = 0; k < used.size(); ++k) {
      const auto position = static_cast<std::size_t>(used[k]);
      fields[k] = position < values.size() ? values[position] : 0;
    }
    return expression->evaluate(0, 0, 0, fields);
  };
}

}  // namespace geomesh
