// MshDecoder: reads MSH values as text or binary from memory; bad input throws MshReadError.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace geomesh {

// Reads the values of an MSH file held in memory, as text tokens or raw binary values (the
// counterpart of MshEncoder), tracking the line number for error messages. Every read checks
// the input: a malformed value or a premature end throws MshReadError.
class MshDecoder {
 public:
  MshDecoder(std::string_view data, std::string name) : data_(data), name_(std::move(name)) {}

  void setBinary(bool binary) { binary_ = binary; }
  bool binary() const { return binary_; }
  bool atEnd();  // only whitespace left (text)

  std::uint64_t size();  // size_t in binary
  int integer();         // int in binary
  double real();         // double in binary; must be finite
  // A whole line, without its line break (binary data is never read this way).
  std::string_view line();
  std::string_view token();
  std::string quoted();  // a "double-quoted" string
  // Skips lines up to and including `marker` (a line of its own).
  void skipPast(std::string_view marker);

  [[noreturn]] void fail(const std::string& message) const;
  int lineNumber() const { return line_; }
  std::size_t remaining() const { return data_.size() - pos_; }

 private:
  void skipSpace();
  template <class T>
  T raw();
  template <class T>
  T number(std::string_view what);

  std::string_view data_;
  std::string name_;
  std::size_t pos_ = 0;
  int line_ = 1;
  bool binary_ = false;
};

}  // namespace geomesh
