// Base64 (RFC 4648, with padding): how binary arrays travel inside text such as a web page.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace geomesh {

std::string encodeBase64(std::string_view bytes);
std::string encodeBase64(std::span<const std::uint8_t> bytes);
// Nullopt when `text` is not padded base64.
std::optional<std::vector<std::uint8_t>> decodeBase64(const std::string& text);

// The values' bytes, little-endian whatever the machine, as base64.
std::string base64OfFloats(std::span<const float> values);
std::string base64OfUint32s(std::span<const std::uint32_t> values);

}  // namespace geomesh
