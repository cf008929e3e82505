// MathExpression: a MathEval field's formula, compiled once and evaluated per point.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace geomesh {

class ExpressionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A MathEval field's formula, compiled once to a postfix program and evaluated per point.
// Grammar: numbers, x y z, F<n> (the value of field n), + - * / ^ (right-associative), unary
// minus, parentheses, and the functions Sqrt Exp Log Log10 Sin Cos Tan Asin Acos Atan Sinh
// Cosh Tanh Abs Fabs Floor Ceil (one argument), Atan2 Fmod Hypot Min Max Pow (two), any letter
// case; the constant Pi. Throws ExpressionError naming the position of a syntax error.
class MathExpression {
 public:
  explicit MathExpression(const std::string& text);

  // Tags of the fields the formula reads (F<n>), each once.
  const std::vector<int>& fieldsUsed() const { return fields_; }
  // The value at (x, y, z); fieldValues[k] is the value of fieldsUsed()[k] there.
  double evaluate(double x, double y, double z, std::span<const double> fieldValues) const;

  enum class Op : unsigned char {
    Number, X, Y, Z, Field, Neg, Add, Sub, Mul, Div, Pow, Call1, Call2
  };
  struct Instruction {
    Op op;
    int index = 0;   // Field: position in fieldsUsed(); Call: function number
    double value = 0;  // Number
  };

 private:
  std::vector<Instruction> program_;
  std::vector<int> fields_;
};

}  // namespace geomesh
