// PNG encoding and decoding of RgbImage through libpng's simplified interface, and the
// reduction of an image's colours to a palette.
#include "io/rgb_image.h"

#include <png.h>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace geomesh {

namespace {

std::string pngFailure(const char* what, const png_image& image) {
  return std::string(what) + ": " + (image.message[0] ? image.message : "libpng failed");
}

std::uint32_t packed(const std::uint8_t* rgb) {
  return std::uint32_t(rgb[0]) << 16 | std::uint32_t(rgb[1]) << 8 | rgb[2];
}

// The image's colours in increasing order, if there are at most 256 of them; else empty.
std::vector<std::uint32_t> paletteOf(const RgbImage& image) {
  std::unordered_set<std::uint32_t> colors;
  std::uint32_t last = 0xffffffffu;  // no colour: neighbours are often alike
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) {
    const std::uint32_t color = packed(&image.pixels[i]);
    if (color == last) continue;
    last = color;
    if (colors.insert(color).second && colors.size() > 256) return {};
  }
  std::vector<std::uint32_t> palette(colors.begin(), colors.end());
  std::sort(palette.begin(), palette.end());
  return palette;
}

std::string writePng(png_image& info, const void* pixels, const void* colormap) {
  png_alloc_size_t size = 0;
  // The first call measures, the second writes.
  if (!png_image_write_to_memory(&info, nullptr, &size, 0, pixels, 0, colormap))
    throw std::runtime_error(pngFailure("cannot encode PNG", info));
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&info, bytes.data(), &size, 0, pixels, 0, colormap))
    throw std::runtime_error(pngFailure("cannot encode PNG", info));
  bytes.resize(size);
  return bytes;
}

int squaredDistance(std::uint32_t a, std::uint32_t b) {
  int sum = 0;
  for (int shift : {16, 8, 0}) {
    const int d = int(a >> shift & 0xff) - int(b >> shift & 0xff);
    sum += d * d;
  }
  return sum;
}

}  // namespace

void limitColors(RgbImage& image, std::size_t count) {
  std::unordered_map<std::uint32_t, std::size_t> frequency;
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) ++frequency[packed(&image.pixels[i])];
  if (frequency.size() <= count) return;
  std::vector<std::pair<std::size_t, std::uint32_t>> byFrequency;
  for (const auto& [color, n] : frequency) byFrequency.emplace_back(n, color);
  std::sort(byFrequency.begin(), byFrequency.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  byFrequency.resize(count);
  std::unordered_map<std::uint32_t, std::uint32_t> replacement;
  for (const auto& [color, n] : frequency) {
    std::uint32_t best = byFrequency.front().second;
    int bestDistance = squaredDistance(color, best);
    for (const auto& [m, kept] : byFrequency) {
      const int d = squaredDistance(color, kept);
      if (d < bestDistance || (d == bestDistance && kept < best)) {
        best = kept;
        bestDistance = d;
      }
    }
    replacement.emplace(color, best);
  }
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) {
    const std::uint32_t color = replacement.at(packed(&image.pixels[i]));
    image.pixels[i] = static_cast<std::uint8_t>(color >> 16);
    image.pixels[i + 1] = static_cast<std::uint8_t>(color >> 8);
    image.pixels[i + 2] = static_cast<std::uint8_t>(color);
  }
}

std::string encodePng(const RgbImage& image) {
  if (image.width <= 0 || image.height <= 0)
    throw std::runtime_error("cannot encode an empty image as PNG");
  png_image info{};
  info.version = PNG_IMAGE_VERSION;
  info.width = static_cast<png_uint_32>(image.width);
  info.height = static_cast<png_uint_32>(image.height);
  const std::vector<std::uint32_t> palette = paletteOf(image);
  if (palette.empty()) {
    info.format = PNG_FORMAT_RGB;
    return writePng(info, image.pixels.data(), nullptr);
  }
  // Few colours (flat shading, antialiasing by a few samples): an indexed image, smaller.
  info.format = PNG_FORMAT_RGB_COLORMAP;
  info.colormap_entries = static_cast<png_uint_32>(palette.size());
  std::vector<std::uint8_t> colormap, indices(image.pixels.size() / 3);
  for (std::uint32_t c : palette)
    colormap.insert(colormap.end(), {std::uint8_t(c >> 16), std::uint8_t(c >> 8), std::uint8_t(c)});
  std::unordered_map<std::uint32_t, std::uint8_t> indexOf;
  for (std::size_t k = 0; k < palette.size(); ++k)
    indexOf.emplace(palette[k], static_cast<std::uint8_t>(k));
  std::uint32_t last = 0xffffffffu;
  std::uint8_t index = 0;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const std::uint32_t color = packed(&image.pixels[3 * i]);
    if (color != last) {
      last = color;
      index = indexOf.at(color);
    }
    indices[i] = index;
  }
  return writePng(info, indices.data(), colormap.data());
}

RgbImage decodePng(const std::string& bytes) {
  png_image info{};
  info.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&info, bytes.data(), bytes.size()))
    throw std::runtime_error(pngFailure("not a PNG file", info));
  info.format = PNG_FORMAT_RGB;
  RgbImage image;
  image.width = static_cast<int>(info.width);
  image.height = static_cast<int>(info.height);
  image.pixels.resize(PNG_IMAGE_SIZE(info));
  const png_color white{255, 255, 255};
  if (!png_image_finish_read(&info, &white, image.pixels.data(), 0, nullptr)) {
    png_image_free(&info);
    throw std::runtime_error(pngFailure("cannot decode PNG", info));
  }
  return image;
}

}  // namespace geomesh
