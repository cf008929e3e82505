// Value's constructors for numbers, lists and strings, and the names of its kinds.
#include "interpreter/value.h"

namespace geomesh {

Value Value::number(double x) {
  Value v;
  v.numbers_ = {x};
  return v;
}

Value Value::list(std::vector<double> xs) {
  Value v;
  v.kind_ = Kind::List;
  v.numbers_ = std::move(xs);
  return v;
}

Value Value::string(std::string s) {
  Value v;
  v.kind_ = Kind::String;
  v.numbers_.clear();
  v.strings_ = {std::move(s)};
  return v;
}

Value Value::stringList(std::vector<std::string> ss) {
  Value v;
  v.kind_ = Kind::StringList;
  v.numbers_.clear();
  v.strings_ = std::move(ss);
  return v;
}

const char* Value::describe() const {
  switch (kind_) {
    case Kind::Number: return "a number";
    case Kind::List: return "a list";
    case Kind::String: return "a string";
    case Kind::StringList: return "a list of strings";
  }
  return "a value";
}

}  // namespace geomesh
