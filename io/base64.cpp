// Base64 encoding and decoding, and little-endian arrays of numbers as base64.
#include "io/base64.h"

#include <bit>
#include <string_view>

#include "io/binary_output.h"

namespace geomesh {

namespace {

constexpr std::string_view kAlphabet =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int sextet(char c) {
  const std::size_t at = kAlphabet.find(c);
  return at == std::string_view::npos ? -1 : static_cast<int>(at);
}

template <class T>
std::string littleEndianBase64(std::span<const T> values) {
  std::string bytes;
  bytes.reserve(sizeof(T) * values.size());
  for (T v : values) appendRaw(bytes, v, std::endian::little);
  return encodeBase64(bytes);
}

}  // namespace

std::string encodeBase64(std::string_view bytes) {
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    const auto byte = [&](std::size_t k) { return std::uint32_t(std::uint8_t(bytes[i + k])); };
    std::uint32_t group = byte(0) << 16;
    if (n > 1) group |= byte(1) << 8;
    if (n > 2) group |= byte(2);
    for (std::size_t k = 0; k < 4; ++k)
      text += k <= n ? kAlphabet[(group >> (18 - 6 * k)) & 63] : '=';
  }
  return text;
}

std::string encodeBase64(std::span<const std::uint8_t> bytes) {
  return encodeBase64(
      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

std::optional<std::vector<std::uint8_t>> decodeBase64(const std::string& text) {
  if (text.size() % 4 != 0) return std::nullopt;
  std::vector<std::uint8_t> bytes;
  bytes.reserve(text.size() / 4 * 3);
  for (std::size_t i = 0; i < text.size(); i += 4) {
    const bool last = i + 4 == text.size();
    const int pad = last ? (text[i + 3] == '=') + (text[i + 2] == '=') : 0;
    std::uint32_t group = 0;
    for (int k = 0; k < 4; ++k) {
      const int value = k >= 4 - pad ? 0 : sextet(text[i + k]);
      if (value < 0) return std::nullopt;
      group = group << 6 | static_cast<std::uint32_t>(value);
    }
    for (int k = 0; k < 3 - pad; ++k)
      bytes.push_back(static_cast<std::uint8_t>(group >> (16 - 8 * k)));
  }
  return bytes;
}

std::string base64OfFloats(std::span<const float> values) {
  return littleEndianBase64(values);
}

std::string base64OfUint32s(std::span<const std::uint32_t> values) {
  return littleEndianBase64(values);
}

}  // namespace geomesh
