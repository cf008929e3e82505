// OptionRegistry: a session's General., Geometry. and Mesh. options, defaults and old names.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "stdlib/option_table.h"

namespace geomesh {

// The General., Geometry. and Mesh. options of one session: each has a name, a type, a
// default, a help line and possibly an old name (alias) that still works. Names are
// case-sensitive, as in Gmsh.
class OptionRegistry {
 public:
  struct Option {
    std::string name;
    OptionType type = OptionType::Number;
    double number = 0;
    std::string text;
    double defaultNumber = 0;
    std::string defaultText;
    std::string help;
    std::vector<std::string> aliases;
  };

  OptionRegistry();

  // Number and colour options.
  bool hasNumber(std::string_view name) const;
  double number(std::string_view name) const;          // throws std::out_of_range if unknown
  void setNumber(std::string_view name, double value);  // throws std::out_of_range if unknown

  bool hasString(std::string_view name) const;
  std::string string(std::string_view name) const;            // throws std::out_of_range
  void setString(std::string_view name, std::string value);  // throws std::out_of_range

  // The option called `name` or one of its aliases; null if none.
  const Option* find(std::string_view name) const;
  // Every option, sorted by name.
  const std::vector<Option>& all() const { return options_; }
  // Known names (aliases included) close to a misspelled `name`, best first.
  std::vector<std::string> suggestions(std::string_view name) const;
  // Back to the defaults.
  void reset();

 private:
  Option* findMutable(std::string_view name);
  const Option& require(std::string_view name, bool wantNumber) const;

  std::vector<Option> options_;
  std::map<std::string, std::size_t, std::less<>> index_;  // names and aliases
  std::vector<std::string> names_;
};

// One line of the option listing (-help-options), in script syntax:
//   Mesh.MeshSizeMin = 0; // lower bound on the element size (old name: ...)
std::string optionListingLine(const OptionRegistry::Option& option);

}  // namespace geomesh
