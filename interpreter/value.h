// Value: what a script expression evaluates to: number, list, string or list of strings.
#pragma once

#include <string>
#include <vector>

#include "stdlib/clamped_integer.h"

namespace geomesh {

// What an expression evaluates to: a number, a list of numbers, a string or a list of
// strings. A number is also a list of one number where a list is expected.
class Value {
 public:
  enum class Kind { Number, List, String, StringList };

  Value() = default;
  static Value number(double x);
  static Value list(std::vector<double> xs);
  static Value string(std::string s);
  static Value stringList(std::vector<std::string> ss);

  Kind kind() const { return kind_; }
  bool isNumeric() const { return kind_ == Kind::Number || kind_ == Kind::List; }
  bool isText() const { return kind_ == Kind::String || kind_ == Kind::StringList; }
  bool isScalar() const { return kind_ == Kind::Number || kind_ == Kind::String; }

  // Valid when isNumeric(): the numbers (one for a Number).
  const std::vector<double>& numbers() const { return numbers_; }
  std::vector<double>& numbers() { return numbers_; }
  // Valid when isText(): the strings (one for a String).
  const std::vector<std::string>& strings() const { return strings_; }
  std::vector<std::string>& strings() { return strings_; }
  std::size_t size() const { return isNumeric() ? numbers_.size() : strings_.size(); }

  // Name of the kind for messages: "a number", "a list", "a string", "a list of strings".
  const char* describe() const;

 private:
  Kind kind_ = Kind::Number;
  std::vector<double> numbers_{0.0};
  std::vector<std::string> strings_;
};

}  // namespace geomesh
