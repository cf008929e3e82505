// Lookups of the script's reserved words: commands, tail words, attributes, functions.
#pragma once

#include <span>
#include <string_view>

namespace geomesh {

// Words that start or continue a command (Point, Plane, Surface, Mesh, ...).
std::span<const std::string_view> commandWords();
// Words that only follow a shape: In, Using, Progression, Left, ...
std::span<const std::string_view> tailWords();
// Attribute names inside DefineConstant[...] (Name, Min, Max, Choices, ...).
std::span<const std::string_view> attributeNames();
// Names of the built-in functions (Sqrt, StrCat, Sprintf, ...).
std::span<const std::string_view> functionNames();
bool isFunctionName(std::string_view name);

}  // namespace geomesh
