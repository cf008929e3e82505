// RgbImage: 8-bit RGB pixels, row by row from the top; and its PNG encoding (libpng).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/picture.h"

namespace geomesh {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // 3 bytes per pixel

  RgbImage() = default;
  RgbImage(int w, int h, Rgb fill) : width(w), height(h), pixels(std::size_t(w) * h * 3) {
    for (std::size_t i = 0; i < pixels.size(); i += 3) {
      pixels[i] = fill.r;
      pixels[i + 1] = fill.g;
      pixels[i + 2] = fill.b;
    }
  }
  Rgb at(int x, int y) const {
    const std::size_t i = (std::size_t(y) * width + x) * 3;
    return {pixels[i], pixels[i + 1], pixels[i + 2]};
  }
};

// Replaces the colours of an image that has more than `count` by the nearest of its `count`
// most frequent ones (ties: the lower packed value), so that it encodes as an indexed PNG;
// a picture of flat-shaded faces changes little. Deterministic.
void limitColors(RgbImage& image, std::size_t count);

// The PNG file of the image: indexed when it has at most 256 colours, else 8-bit RGB; no time
// or text chunk, so that the same image gives the same bytes. Throws std::runtime_error with
// libpng's reason if it cannot.
std::string encodePng(const RgbImage& image);
// The pixels of a PNG file, converted to 8-bit RGB (alpha composed over white). Throws
// std::runtime_error with libpng's reason for bytes that are no PNG file.
RgbImage decodePng(const std::string& bytes);

}  // namespace geomesh
