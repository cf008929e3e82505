// formatPrintf: each conversion of a printf format checked and applied to its script value.
#include "stdlib/format.h"

#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "stdlib/clamped_integer.h"

namespace geomesh {

namespace {

template <class T>
std::string printOne(const std::string& spec, T value) {
  int size = std::snprintf(nullptr, 0, spec.c_str(), value);
  if (size < 0) throw std::invalid_argument("bad format '" + spec + "'");
  if (size > 1'000'000) throw std::invalid_argument("format '" + spec + "' gives too long a text");
  std::vector<char> buffer(static_cast<std::size_t>(size) + 1);
  std::snprintf(buffer.data(), buffer.size(), spec.c_str(), value);
  return std::string(buffer.data(), static_cast<std::size_t>(size));
}

const FormatArgument& take(std::span<const FormatArgument> arguments, std::size_t& next,
                           const std::string& spec) {
  if (next >= arguments.size())
    throw std::invalid_argument("not enough arguments for format '" + spec + "'");
  return arguments[next++];
}

double asNumber(const FormatArgument& argument, const std::string& spec) {
  if (const double* x = std::get_if<double>(&argument)) return *x;
  throw std::invalid_argument("format '" + spec + "' needs a number, not a string");
}

std::string convert(std::string spec, char conversion, const FormatArgument& argument) {
  switch (conversion) {
    case 'd': case 'i':
      return printOne(spec + "ll" + conversion,
                      clampedInteger<long long>(asNumber(argument, spec + conversion)));
    case 'o': case 'u': case 'x': case 'X':
      return printOne(spec + "ll" + conversion,
                      static_cast<unsigned long long>(
                          clampedInteger<long long>(asNumber(argument, spec + conversion))));
    case 'c':
      return printOne(spec + conversion,
                      clampedInteger<int>(asNumber(argument, spec + conversion)));
    case 's':
      if (const std::string* s = std::get_if<std::string>(&argument))
        return printOne(spec + conversion, s->c_str());
      return printOne(spec + "g", std::get<double>(argument));
    default:
      return printOne(spec + conversion, asNumber(argument, spec + conversion));
  }
}

}  // namespace

std::string formatPrintf(std::string_view format, std::span<const FormatArgument> arguments) {
  std::string out;
  std::size_t next = 0;
  for (std::size_t i = 0; i < format.size(); ++i) {
    if (format[i] != '%') {
      out += format[i];
      continue;
    }
    if (i + 1 < format.size() && format[i + 1] == '%') {
      out += '%';
      ++i;
      continue;
    }
    std::string spec = "%";
    std::size_t j = i + 1;
    while (j < format.size() && std::string_view("-+ #0").find(format[j]) != std::string_view::npos)
      spec += format[j++];
    while (j < format.size() &&
           (std::isdigit(static_cast<unsigned char>(format[j])) || format[j] == '.'))
      spec += format[j++];
    constexpr std::string_view kLengthModifiers = "hlLqjzt";
    while (j < format.size() && kLengthModifiers.find(format[j]) != std::string_view::npos) ++j;
    if (j >= format.size() ||
        std::string_view("diouxXcseEfFgGaA").find(format[j]) == std::string_view::npos)
      throw std::invalid_argument("unknown conversion in format '" +
                                  std::string(format.substr(i, j - i + 1)) + "'");
    out += convert(spec, format[j], take(arguments, next, spec + format[j]));
    i = j;
  }
  if (next < arguments.size())
    throw std::invalid_argument(std::to_string(arguments.size() - next) + " extra argument" +
                                (arguments.size() - next == 1 ? "" : "s") + " for the format");
  return out;
}

}  // namespace geomesh
