// OptionRegistry: built from the option tables; lookups by name or alias; -help-options lines.
#include "stdlib/options.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "stdlib/clamped_integer.h"
#include "stdlib/edit_distance.h"
#include "stdlib/system_info.h"

namespace geomesh {

namespace {

OptionRegistry::Option fromSpec(const OptionSpec& spec) {
  OptionRegistry::Option option;
  option.name = spec.name;
  option.type = spec.type;
  option.number = option.defaultNumber = spec.number;
  option.text = option.defaultText = spec.text;
  option.help = spec.help;
  for (std::string_view rest = spec.aliases; !rest.empty();) {
    const auto space = rest.find(' ');
    option.aliases.emplace_back(rest.substr(0, space));
    rest = space == std::string_view::npos ? std::string_view() : rest.substr(space + 1);
  }
  return option;
}

}  // namespace

OptionRegistry::OptionRegistry() {
  for (auto table : {generalOptions(), geometryOptions(), meshOptions(), printOptions()})
    for (const auto& spec : table) options_.push_back(fromSpec(spec));
  std::sort(options_.begin(), options_.end(),
            [](const Option& a, const Option& b) { return a.name < b.name; });
  for (std::size_t i = 0; i < options_.size(); ++i) {
    index_.emplace(options_[i].name, i);
    names_.push_back(options_[i].name);
    for (const auto& alias : options_[i].aliases) {
      index_.emplace(alias, i);
      names_.push_back(alias);
    }
  }
  Option& executable = *findMutable("General.ExecutableFileName");
  executable.text = executable.defaultText = executablePath();
}

const OptionRegistry::Option* OptionRegistry::find(std::string_view name) const {
  auto it = index_.find(name);
  return it == index_.end() ? nullptr : &options_[it->second];
}

OptionRegistry::Option* OptionRegistry::findMutable(std::string_view name) {
  auto it = index_.find(name);
  return it == index_.end() ? nullptr : &options_[it->second];
}

const OptionRegistry::Option& OptionRegistry::require(std::string_view name,
                                                      bool wantNumber) const {
  const Option* option = find(name);
  if (!option || (option->type == OptionType::String) == wantNumber)
    throw std::out_of_range("unknown " + std::string(wantNumber ? "number" : "string") +
                            " option '" + std::string(name) + "'");
  return *option;
}

bool OptionRegistry::hasNumber(std::string_view name) const {
  const Option* option = find(name);
  return option && option->type != OptionType::String;
}

double OptionRegistry::number(std::string_view name) const { return require(name, true).number; }

void OptionRegistry::setNumber(std::string_view name, double value) {
  require(name, true);
  findMutable(name)->number = value;
}

bool OptionRegistry::hasString(std::string_view name) const {
  const Option* option = find(name);
  return option && option->type == OptionType::String;
}

std::string OptionRegistry::string(std::string_view name) const {
  return require(name, false).text;
}

void OptionRegistry::setString(std::string_view name, std::string value) {
  require(name, false);
  findMutable(name)->text = std::move(value);
}

std::vector<std::string> OptionRegistry::suggestions(std::string_view name) const {
  return closestNames(name, names_);
}

std::string optionListingLine(const OptionRegistry::Option& option) {
  std::string line = option.name + " = ";
  char buffer[64];
  if (option.type == OptionType::String) {
    line += "\"" + option.text + "\"";
  } else if (option.type == OptionType::Color) {
    const auto packed = clampedInteger<long long>(option.number);
    std::snprintf(buffer, sizeof buffer, "{%lld,%lld,%lld}", (packed >> 16) & 255,
                  (packed >> 8) & 255, packed & 255);
    line += buffer;
  } else {
    std::snprintf(buffer, sizeof buffer, "%.16g", option.number);
    line += buffer;
  }
  line += "; // " + option.help;
  for (const auto& alias : option.aliases) line += " (old name: " + alias + ")";
  return line;
}

void OptionRegistry::reset() {
  for (auto& option : options_) {
    option.number = option.defaultNumber;
    option.text = option.defaultText;
  }
}

}  // namespace geomesh
