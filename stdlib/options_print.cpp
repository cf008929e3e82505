// The Print. options that batch runs use: the size of the pictures written (.png, .svg).
// Defaults follow the reference manual; the help lines are this project's own words.
#include "stdlib/option_table.h"

namespace geomesh {

std::span<const OptionSpec> printOptions() {
  using enum OptionType;
  static constexpr OptionSpec kOptions[] = {
      {"Print.Height", Number, -1, "", "picture height, pixels; <= 0: General.GraphicsHeight", ""},
      {"Print.Width", Number, -1, "", "picture width in pixels; <= 0: General.GraphicsWidth", ""},
  };
  return kOptions;
}

}  // namespace geomesh
