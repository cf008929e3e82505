// ViewScanner: checked reads of words and binary values from a view file held in memory,
// failing with ViewReadError located at "path:line:col" (text) or "path: byte N" (binary).
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "io/view_files.h"

namespace geomesh {

// Reads a file held in memory as whitespace-separated words, whole lines or raw binary
// values. Every read checks its input; a failure names the start of the word (or the first
// byte of the binary value) it was reading.
class ViewScanner {
 public:
  ViewScanner(std::string_view data, std::string path) : data_(data), path_(std::move(path)) {}

  bool atEnd();                 // only whitespace left
  std::string_view word();      // fails at the end of the input
  std::string_view peekWord();  // empty at the end
  // The rest of the current line (without its line break and trailing blanks), consuming the
  // line break.
  std::string_view line();
  // A word as a number: an integer type or double (finite).
  template <class T>
  T number(std::string_view what);
  double real() { return number<double>("a number"); }
  // The longest prefix of the next word that reads as a number; the rest of the word is left
  // for the next read. `maxLength` caps the prefix (for backtracking over an ambiguous word).
  double realPrefix(std::size_t maxLength = std::string_view::npos);
  // `count` raw bytes; binary values in `order` (4- or 8-byte reals).
  std::string_view bytes(std::size_t count);
  template <class T>
  T raw(std::endian order);
  double rawReal(std::endian order, int size);

  void skipSpace();
  // The byte offset of the next read; move back or forth to an offset already checked.
  std::size_t offset() const { return pos_; }
  void seek(std::size_t offset) { pos_ = offset; }
  std::size_t remaining() const { return data_.size() - pos_; }
  std::string_view data() const { return data_; }

  // Fails at the start of the last read (`binary`: located as a byte offset).
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void failAt(std::size_t offset, const std::string& message) const;
  void setBinary(bool binary) { binary_ = binary; }
  bool binary() const { return binary_; }

 private:
  std::string_view data_;
  std::string path_;
  std::size_t pos_ = 0;
  std::size_t start_ = 0;  // where the last read began
  bool binary_ = false;    // whether failures are located as byte offsets
};

// `text` read whole as a number of type T; false if it is not one (or not finite).
template <class T>
bool parseWhole(std::string_view text, T& value);

template <class T>
T ViewScanner::number(std::string_view what) {
  const std::string_view w = word();
  T v{};
  if (!parseWhole(w, v))
    fail("expected " + std::string(what) + ", found '" + std::string(w.substr(0, 40)) + "'");
  return v;
}

template <class T>
T ViewScanner::raw(std::endian order) {
  start_ = pos_;
  if (remaining() < sizeof(T)) fail("unexpected end of binary data");
  unsigned char b[sizeof(T)];
  for (std::size_t i = 0; i < sizeof(T); ++i) b[i] = static_cast<unsigned char>(data_[pos_ + i]);
  pos_ += sizeof(T);
  if (order != std::endian::native)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

}  // namespace geomesh
