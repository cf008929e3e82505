// SVG writer: the picture of a mesh (io/picture.h) as vector graphics, one polygon per face in
// painter's order, filled with the face's shaded colour and outlined by a thin dark stroke;
// or, for a mesh of lines only, one path of dark segments. Coordinates are pixels of
// Print.Width x Print.Height (else General.GraphicsWidth x General.GraphicsHeight).
#include <charconv>
#include <cstdio>
#include <ostream>

#include "io/formats.h"
#include "io/picture.h"

namespace geomesh {

namespace {

// A coordinate to a hundredth of a pixel, without trailing zeros.
void writeCoordinate(std::ostream& out, double v) {
  char text[32];
  char* end = std::to_chars(text, text + sizeof text, v, std::chars_format::fixed, 2).ptr;
  while (end[-1] == '0') --end;
  if (end[-1] == '.') --end;
  if (end - text == 2 && text[0] == '-' && text[1] == '0') {  // "-0.001" rounds to "-0"
    out << '0';
    return;
  }
  out.write(text, end - text);
}

void writePoint(std::ostream& out, const Vec3& p) {
  writeCoordinate(out, p.x);
  out << ',';
  writeCoordinate(out, p.y);
}

std::string hexColor(Rgb c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

}  // namespace

void writeSvg(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const Picture picture = composePicture(model, mesh, pictureOptionsOf(options), "svg");
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << picture.width << "\" height=\""
      << picture.height << "\" viewBox=\"0 0 " << picture.width << ' ' << picture.height
      << "\">\n"
      << "<rect width=\"" << picture.width << "\" height=\"" << picture.height << "\" fill=\""
      << hexColor(kPictureBackground) << "\"/>\n";
  if (!picture.faces.empty()) {
    out << "<g stroke=\"" << hexColor(kPictureEdge)
        << "\" stroke-width=\"0.6\" stroke-linejoin=\"round\">\n";
    for (const PictureFace& face : picture.faces) {
      out << "<polygon points=\"";
      for (int k = 0; k < face.cornerCount; ++k) {
        if (k > 0) out << ' ';
        writePoint(out, face.corners[k]);
      }
      out << "\" fill=\"" << hexColor(face.fill) << "\"/>\n";
    }
    out << "</g>\n";
  }
  if (!picture.lines.empty()) {
    out << "<path fill=\"none\" stroke=\"" << hexColor(kPictureEdge)
        << "\" stroke-width=\"1.2\" stroke-linecap=\"round\" d=\"";
    for (std::size_t i = 0; i < picture.lines.size(); ++i) {
      out << (i == 0 ? "M" : " M");
      writePoint(out, picture.lines[i].from);
      out << " L";
      writePoint(out, picture.lines[i].to);
    }
    out << "\"/>\n";
  }
  out << "</svg>\n";
}

}  // namespace geomesh
