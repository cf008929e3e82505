// OptionSpec: one row of the built-in General., Geometry., Mesh. and Print. option tables.
#pragma once

#include <span>
#include <string_view>

namespace geomesh {

// Colours are numbers: red * 65536 + green * 256 + blue.
enum class OptionType { Number, String, Color };

// One row of the built-in option tables.
struct OptionSpec {
  std::string_view name;  // "Mesh.MeshSizeMin"
  OptionType type;
  double number;          // default of number and colour options
  std::string_view text;  // default of string options
  std::string_view help;
  std::string_view aliases;  // old names still accepted, separated by spaces; or empty
};

std::span<const OptionSpec> generalOptions();
std::span<const OptionSpec> geometryOptions();
std::span<const OptionSpec> meshOptions();
std::span<const OptionSpec> printOptions();

}  // namespace geomesh
