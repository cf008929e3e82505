// formatPrintf: printf-style formatting of script values for Printf and Sprintf.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace geomesh {

using FormatArgument = std::variant<double, std::string>;

// printf-style formatting of script values (Printf, Sprintf): %d %i %o %u %x %X %c take the
// integer part of a number, %e %f %g %a (and upper-case forms) a number, %s a string, %% a
// percent sign. Flags, width and precision are honoured; length modifiers (l, h, ...) are
// accepted and ignored. Throws std::invalid_argument when the arguments do not match.
std::string formatPrintf(std::string_view format, std::span<const FormatArgument> arguments);

}  // namespace geomesh
