// The rasterizer of pictures: faces split into triangles, each sample covered by the nearest
// face (a depth buffer; ties go to the face drawn later, which painter's order makes the
// nearer), edges darkened by their distance to the sample, then samples averaged per pixel.
#include "io/picture_raster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geomesh {

namespace {

// Half the width of an element edge in output pixels: a shared edge is drawn from both sides.
constexpr double kEdgeHalfWidth = 0.5;
constexpr double kLineHalfWidth = 0.6;

class SampleBuffer {
 public:
  SampleBuffer(int width, int height)
      : width_(width),
        height_(height),
        color_(std::size_t(width) * height, kPictureBackground),
        depth_(std::size_t(width) * height, -std::numeric_limits<float>::infinity()) {}

  int width() const { return width_; }
  int height() const { return height_; }
  // Keeps the colour if the sample is at least as near as what is there.
  void cover(int x, int y, float z, Rgb color) {
    const std::size_t i = std::size_t(y) * width_ + x;
    if (z < depth_[i]) return;
    depth_[i] = z;
    color_[i] = color;
  }
  void paint(int x, int y, Rgb color) { color_[std::size_t(y) * width_ + x] = color; }
  Rgb at(int x, int y) const { return color_[std::size_t(y) * width_ + x]; }

 private:
  int width_, height_;
  std::vector<Rgb> color_;
  std::vector<float> depth_;
};

// The line through a and b as A x + B y + C, positive on the left of a -> b (y down: seen
// on screen, on the right). Swapping a and b negates A, B and C exactly, so that two triangles
// sharing a side agree to the last bit on which side of it a sample lies.
struct EdgeLine {
  double a = 0, b = 0, c = 0;
  EdgeLine(Vec3 from, Vec3 to)
      : a(from.y - to.y), b(to.x - from.x), c(from.x * to.y - from.y * to.x) {}
  double at(double x, double y) const { return a * x + b * y + c; }
};

// Fills the samples whose centres the triangle covers; `sides` says which of its sides
// (p0p1, p1p2, p2p0) are element edges, drawn dark within `edgeHalfWidth` samples. A sample
// on a side belongs to one of the two triangles sharing the side only: the one for which the
// side runs down the buffer, or leftwards if it is level.
void fillTriangle(SampleBuffer& buffer, std::array<Vec3, 3> p, std::array<bool, 3> sides,
                  Rgb fill, double edgeHalfWidth) {
  double area = EdgeLine(p[0], p[1]).at(p[2].x, p[2].y);
  if (area == 0 || !std::isfinite(area)) return;
  if (area < 0) {
    std::swap(p[1], p[2]);
    std::swap(sides[0], sides[2]);
    area = -area;
  }
  std::array<EdgeLine, 3> lines{EdgeLine(p[0], p[1]), EdgeLine(p[1], p[2]), EdgeLine(p[2], p[0])};
  std::array<bool, 3> owns{};
  std::array<double, 3> band{};  // the edge function's value at the edge band's inner border
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = p[(i + 1) % 3] - p[i];
    owns[i] = d.y > 0 || (d.y == 0 && d.x < 0);
    band[i] = sides[i] ? edgeHalfWidth * std::hypot(d.x, d.y) : -1;
  }
  const auto [minX, maxX] = std::minmax({p[0].x, p[1].x, p[2].x});
  const auto [minY, maxY] = std::minmax({p[0].y, p[1].y, p[2].y});
  const int x0 = std::max(0, static_cast<int>(std::floor(minX - 0.5)));
  const int x1 = std::min(buffer.width() - 1, static_cast<int>(std::ceil(maxX)));
  const int y0 = std::max(0, static_cast<int>(std::floor(minY - 0.5)));
  const int y1 = std::min(buffer.height() - 1, static_cast<int>(std::ceil(maxY)));
  const double inverseArea = 1 / area;
  for (int y = y0; y <= y1; ++y) {
    const double qy = y + 0.5;
    std::array<double, 3> row;
    for (int i = 0; i < 3; ++i) row[i] = lines[i].b * qy + lines[i].c;
    for (int x = x0; x <= x1; ++x) {
      const double qx = x + 0.5;
      std::array<double, 3> e;
      bool inside = true;
      for (int i = 0; i < 3 && inside; ++i) {
        e[i] = lines[i].a * qx + row[i];
        inside = e[i] > 0 || (e[i] == 0 && owns[i]);
      }
      if (!inside) continue;
      // Side i is opposite corner i + 2: its edge function weighs that corner.
      const double z = (e[1] * p[0].z + e[2] * p[1].z + e[0] * p[2].z) * inverseArea;
      const bool onEdge = e[0] < band[0] || e[1] < band[1] || e[2] < band[2];
      buffer.cover(x, y, static_cast<float>(z), onEdge ? kPictureEdge : fill);
    }
  }
}

void fillFace(SampleBuffer& buffer, const PictureFace& face, int s) {
  std::array<Vec3, 4> c{};
  for (int k = 0; k < face.cornerCount; ++k)
    c[k] = {face.corners[k].x * s, face.corners[k].y * s, face.corners[k].z};
  const double halfWidth = kEdgeHalfWidth * s;
  if (face.cornerCount == 3)
    return fillTriangle(buffer, {c[0], c[1], c[2]}, {true, true, true}, face.fill, halfWidth);
  // A quadrangle as two triangles sharing the diagonal 0-2, which is no element edge.
  fillTriangle(buffer, {c[0], c[1], c[2]}, {true, true, false}, face.fill, halfWidth);
  fillTriangle(buffer, {c[0], c[2], c[3]}, {false, true, true}, face.fill, halfWidth);
}

// Paints the samples within the half width of the segment.
void strokeLine(SampleBuffer& buffer, const PictureLine& line, int s) {
  const Vec3 a{line.from.x * s, line.from.y * s, 0}, b{line.to.x * s, line.to.y * s, 0};
  const double r = kLineHalfWidth * s;
  const Vec3 d = b - a;
  const double length2 = dot(d, d);
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min(a.x, b.x) - r)));
  const int x1 = std::min(buffer.width() - 1, static_cast<int>(std::ceil(std::max(a.x, b.x) + r)));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min(a.y, b.y) - r)));
  const int y1 = std::min(buffer.height() - 1, static_cast<int>(std::ceil(std::max(a.y, b.y) + r)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Vec3 q{x + 0.5, y + 0.5, 0};
      const double t = length2 > 0 ? std::clamp(dot(q - a, d) / length2, 0.0, 1.0) : 0;
      if (norm(q - (a + t * d)) <= r) buffer.paint(x, y, kPictureEdge);
    }
}

}  // namespace

int defaultSupersampling(int width, int height) {
  return double(width) * height <= 4e6 ? 2 : 1;
}

RgbImage rasterizePicture(const Picture& picture, int supersampling) {
  const int s = std::max(1, supersampling);
  SampleBuffer buffer(picture.width * s, picture.height * s);
  for (const PictureFace& face : picture.faces) fillFace(buffer, face, s);
  for (const PictureLine& line : picture.lines) strokeLine(buffer, line, s);

  RgbImage image(picture.width, picture.height, kPictureBackground);
  const int samples = s * s;
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x) {
      int r = 0, g = 0, b = 0;
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
          const Rgb c = buffer.at(x * s + i, y * s + j);
          r += c.r;
          g += c.g;
          b += c.b;
        }
      std::uint8_t* pixel = &image.pixels[(std::size_t(y) * picture.width + x) * 3];
      pixel[0] = static_cast<std::uint8_t>((r + samples / 2) / samples);
      pixel[1] = static_cast<std::uint8_t>((g + samples / 2) / samples);
      pixel[2] = static_cast<std::uint8_t>((b + samples / 2) / samples);
    }
  return image;
}

}  // namespace geomesh
