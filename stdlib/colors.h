// namedColor and colorNames: X11 colour names to packed RGB values, as colour options hold.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace geomesh {

// The colour called `name` (Red, LightBlue, Gray50, ...; case matters), packed like colour
// options: red * 65536 + green * 256 + blue. Null for an unknown name.
std::optional<double> namedColor(std::string_view name);
// Every colour name, for suggestions.
std::vector<std::string> colorNames();

}  // namespace geomesh
