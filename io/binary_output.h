// appendRaw: binary values in a chosen byte order, for the writers of binary formats.
#pragma once

#include <bit>
#include <cstring>
#include <string>
#include <utility>

namespace geomesh {

// Appends the bytes of `v` to `bytes`, most significant first when `order` is big-endian.
template <class T>
void appendRaw(std::string& bytes, T v, std::endian order) {
  char raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  if (order != std::endian::native)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  bytes.append(raw, sizeof(T));
}

}  // namespace geomesh
