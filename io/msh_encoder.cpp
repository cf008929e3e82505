// MshEncoder: buffered output of MSH values as text or little-endian binary.
#include "io/msh_encoder.h"

#include <charconv>
#include <cstring>

namespace geomesh {

namespace {
constexpr std::size_t kFlushThreshold = 1 << 20;
}

template <class T>
void MshEncoder::raw(T v) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  buffer_.append(bytes, sizeof(T));
  if (buffer_.size() > kFlushThreshold) flush();
}

void MshEncoder::separate() {
  if (!lineStart_) buffer_ += ' ';
  lineStart_ = false;
}

void MshEncoder::size(std::uint64_t v) {
  if (binary_) return raw(v);
  separate();
  char digits[24];
  buffer_.append(digits, std::to_chars(digits, digits + sizeof digits, v).ptr);
}

void MshEncoder::integer(int v) {
  if (binary_) return raw(v);
  separate();
  char digits[16];
  buffer_.append(digits, std::to_chars(digits, digits + sizeof digits, v).ptr);
}

void MshEncoder::real(double v) {
  if (binary_) return raw(v);
  separate();
  char digits[32];
  auto end = std::to_chars(digits, digits + sizeof digits, v, std::chars_format::general, 16);
  buffer_.append(digits, end.ptr);
}

void MshEncoder::endLine(bool trailingSpace) {
  if (binary_) return;
  if (trailingSpace) buffer_ += ' ';
  buffer_ += '\n';
  lineStart_ = true;
  if (buffer_.size() > kFlushThreshold) flush();
}

void MshEncoder::text(std::string_view s) {
  buffer_.append(s);
  lineStart_ = s.empty() ? lineStart_ : s.back() == '\n';
  if (buffer_.size() > kFlushThreshold) flush();
}

void MshEncoder::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

}  // namespace geomesh
