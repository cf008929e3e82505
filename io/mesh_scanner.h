// MeshScanner and MeshReadError: checked reads of text words and binary values from a mesh file
// held in memory, for the readers of the formats other than MSH.
#pragma once

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace geomesh {

// A malformed or unsupported mesh file; the message starts with "name:line: ".
class MeshReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The type of a binary number: its size in bytes, and whether it is a signed integer ('i'), an
// unsigned one ('u') or floating-point ('f').
struct NumberType {
  std::size_t bytes = 0;
  char kind = 'i';
};

// Reads a file held in memory as words, lines or raw binary values, tracking the line number
// for error messages. Every read checks the input: a malformed value or a premature end throws
// MeshReadError naming the file and the line (for binary data, the line where it starts).
class MeshScanner {
 public:
  MeshScanner(std::string_view data, std::string name) : data_(data), name_(std::move(name)) {}

  bool atEnd();  // only whitespace left
  // The next whitespace-separated word; fails at the end of the input.
  std::string_view word();
  // The next word without consuming it; empty at the end of the input.
  std::string_view peekWord();
  // The rest of the current line without its line break and trailing spaces. The line break is
  // consumed by the next read, so that an error about the line names it.
  std::string_view line();
  bool hasLine();  // whether line() has a line to return, empty or not
  // Whether the next line starts with `text`, without skipping anything (for binary files).
  bool startsWith(std::string_view text);
  // A word read as a number of type T (an integer type or double): double must be finite.
  template <class T>
  T number(std::string_view what);
  double real() { return number<double>("a number"); }

  // A binary value of type T in byte order `order`.
  template <class T>
  T raw(std::endian order);
  // A binary number of any NumberType as a double (exact for the integers mesh files hold);
  // floating-point numbers must be finite.
  double rawNumber(NumberType type, std::endian order);
  void skip(std::size_t bytes);

  // Throws MeshReadError naming the file and `line` (0: the current line).
  [[noreturn]] void fail(const std::string& message, int line = 0) const;
  int lineNumber() const { return line_; }
  std::size_t remaining() const { return data_.size() - pos_; }

 private:
  void skipSpace();
  void endLine();  // consumes the line break left by line()

  std::string_view data_;
  std::string name_;
  std::size_t pos_ = 0;
  int line_ = 1;
  bool lineBreakPending_ = false;
};

// The whitespace-separated words of a line.
std::vector<std::string_view> wordsOf(std::string_view line);
// `text` in lower case (ASCII letters only).
std::string lowercase(std::string_view text);

// `text` as a number of type T; a malformed number fails through `scanner`.
template <class T>
T parseNumber(const MeshScanner& scanner, std::string_view text, std::string_view what) {
  T v{};
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') ++first;  // from_chars refuses '+'
  const auto [end, error] = std::from_chars(first, last, v);
  if (error != std::errc() || end != last || first == last)
    scanner.fail("expected " + std::string(what) + ", found '" + std::string(text.substr(0, 40)) +
                 "'");
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(v))
      scanner.fail("non-finite number '" + std::string(text.substr(0, 40)) + "'");
  return v;
}

template <class T>
T MeshScanner::number(std::string_view what) {
  return parseNumber<T>(*this, word(), what);
}

template <class T>
T MeshScanner::raw(std::endian order) {
  endLine();
  if (remaining() < sizeof(T)) fail("unexpected end of binary data");
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, data_.data() + pos_, sizeof(T));
  pos_ += sizeof(T);
  if (order != std::endian::native)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  T v;
  std::memcpy(&v, bytes, sizeof(T));
  return v;
}

}  // namespace geomesh
