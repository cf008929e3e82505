// MathExpression: a recursive-descent compiler of MathEval formulas to a postfix program.
#include "mesh/sizes/math_expression.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace geomesh {
namespace {

using Op = MathExpression::Op;
using Instruction = MathExpression::Instruction;

constexpr const char* kUnary[] = {"sqrt", "exp",  "log",  "log10", "sin",  "cos",
                                  "tan",  "asin", "acos", "atan",  "sinh", "cosh",
                                  "tanh", "abs",  "fabs", "floor", "ceil"};
constexpr const char* kBinary[] = {"atan2", "fmod", "hypot", "min", "max", "pow"};

double applyUnary(int f, double a) {
  switch (f) {
    case 0: return std::sqrt(a);
    case 1: return std::exp(a);
    case 2: return std::log(a);
    case 3: return std::log10(a);
    case 4: return std::sin(a);
    case 5: return std::cos(a);
    case 6: return std::tan(a);
    case 7: return std::asin(a);
    case 8: return std::acos(a);
    case 9: return std::atan(a);
    case 10: return std::sinh(a);
    case 11: return std::cosh(a);
    case 12: return std::tanh(a);
    case 13:
    case 14: return std::abs(a);
    case 15: return std::floor(a);
    default: return std::ceil(a);
  }
}

double applyBinary(int f, double a, double b) {
  switch (f) {
    case 0: return std::atan2(a, b);
    case 1: return std::fmod(a, b);
    case 2: return std::hypot(a, b);
    case 3: return std::min(a, b);
    case 4: return std::max(a, b);
    default: return std::pow(a, b);
  }
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Recursive descent: sum := product (('+'|'-') product)*; product := power (('*'|'/') power)*;
// power := unary ('^' power)?; unary := '-' unary | '+' unary | primary.
class Compiler {
 public:
  Compiler(const std::string& text, std::vector<Instruction>& program, std::vector<int>& fields)
      : s_(text), program_(program), fields_(fields) {}

  void run() {
    sum();
    skipSpace();
    if (pos_ != s_.size()) fail("unexpected '" + std::string(1, s_[pos_]) + "'");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ExpressionError("in \"" + s_ + "\" at character " + std::to_string(pos_ + 1) + ": " +
                          what);
  }
  void skipSpace() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skipSpace();
    if (pos_ < s_.size() && s_[pos_] == c) return ++pos_, true;
    return false;
  }
  void expect(char c) {
    if (!accept(c)) fail(std::string("expected '") + c + "'");
  }
  void emit(Op op, int index = 0, double value = 0) { program_.push_back({op, index, value}); }

  void sum() {
    product();
    for (;;) {
      if (accept('+')) product(), emit(Op::Add);
      else if (accept('-')) product(), emit(Op::Sub);
      else return;
    }
  }
  void product() {
    power();
    for (;;) {
      if (accept('*')) power(), emit(Op::Mul);
      else if (accept('/')) power(), emit(Op::Div);
      else return;
    }
  }
  void power() {
    unary();
    if (accept('^')) power(), emit(Op::Pow);
  }
  void unary() {
    if (accept('-')) return unary(), emit(Op::Neg);
    if (accept('+')) return unary();
    primary();
  }
  void primary() {
    skipSpace();
    if (accept('(')) {
      sum();
      return expect(')');
    }
    if (pos_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '.'))
      return number();
    if (pos_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[pos_]))) return name();
    fail(pos_ < s_.size() ? "unexpected '" + std::string(1, s_[pos_]) + "'"
                          : "unexpected end of the formula");
  }
  void number() {
    const char* begin = s_.c_str() + pos_;
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin) fail("bad number");
    pos_ += static_cast<std::size_t>(end - begin);
    emit(Op::Number, 0, value);
  }
  void name() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() &&
           (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_'))
      ++pos_;
    const std::string word = s_.substr(start, pos_ - start);
    const std::string key = lower(word);
    if (key == "x") return emit(Op::X);
    if (key == "y") return emit(Op::Y);
    if (key == "z") return emit(Op::Z);
    if (key == "pi") return emit(Op::Number, 0, 3.14159265358979323846);
    if (word.size() > 1 && word[0] == 'F' &&
        std::all_of(word.begin() + 1, word.end(), [](char c) { return std::isdigit(c) != 0; }))
      return fieldReference(std::stoi(word.substr(1)));
    call(word, key);
  }
  void fieldReference(int tag) {
    auto it = std::find(fields_.begin(), fields_.end(), tag);
    if (it == fields_.end()) it = fields_.insert(fields_.end(), tag);
    emit(Op::Field, static_cast<int>(it - fields_.begin()));
  }
  void call(const std::string& word, const std::string& key) {
    for (int f = 0; f < static_cast<int>(std::size(kUnary)); ++f)
      if (key == kUnary[f]) {
        expect('(');
        sum();
        expect(')');
        return emit(Op::Call1, f);
      }
    for (int f = 0; f < static_cast<int>(std::size(kBinary)); ++f)
      if (key == kBinary[f]) {
        expect('(');
        sum();
        expect(',');
        sum();
        expect(')');
        return emit(Op::Call2, f);
      }
    fail("unknown name '" + word + "'");
  }

  const std::string& s_;
  std::vector<Instruction>& program_;
  std::vector<int>& fields_;
  std::size_t pos_ = 0;
};

}  // namespace

MathExpression::MathExpression(const std::string& text) {
  Compiler(text, program_, fields_).run();
}

double MathExpression::evaluate(double x, double y, double z,
                                std::span<const double> fieldValues) const {
  constexpr std::size_t kInlineDepth = 64;
  double inlineStack[kInlineDepth];
  std::vector<double> heapStack;
  double* stack = inlineStack;
  if (program_.size() > kInlineDepth) {
    heapStack.resize(program_.size());
    stack = heapStack.data();
  }
  std::size_t top = 0;
  for (const Instruction& in : program_) {
    switch (in.op) {
      case Op::Number: stack[top++] = in.value; break;
      case Op::X: stack[top++] = x; break;
      case Op::Y: stack[top++] = y; break;
      case Op::Z: stack[top++] = z; break;
      case Op::Field: stack[top++] = fieldValues[static_cast<std::size_t>(in.index)]; break;
      case Op::Neg: stack[top - 1] = -stack[top - 1]; break;
      case Op::Call1: stack[top - 1] = applyUnary(in.index, stack[top - 1]); break;
      default: {
        const double b = stack[--top];
        double& a = stack[top - 1];
        switch (in.op) {
          case Op::Add: a += b; break;
          case Op::Sub: a -= b; break;
          case Op::Mul: a *= b; break;
          case Op::Div: a /= b; break;
          case Op::Pow: a = std::pow(a, b); break;
          default: a = applyBinary(in.index, a, b); break;
        }
      }
    }
  }
  return top > 0 ? stack[top - 1] : 0;
}

}  // namespace geomesh
