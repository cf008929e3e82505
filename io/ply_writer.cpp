// PLY writer (Stanford polygon files): the surface triangles and quadrangles of a mesh as
// faces over the vertices they use, in ASCII or (Mesh.Binary) binary_little_endian.
#include <bit>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>

#include "io/binary_output.h"
#include "io/formats.h"
#include "io/surface_content.h"

namespace geomesh {

namespace {

void writeHeader(std::ostream& out, const SurfaceContent& surface, bool binary) {
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
      << "comment geomesh mesh\n"
      << "element vertex " << surface.nodes.size() << '\n'
      << "property double x\nproperty double y\nproperty double z\n"
      << "element face " << surface.faceCount << '\n'
      << "property list uchar int vertex_indices\nend_header\n";
}

void writeBinary(std::ostream& out, const Mesh& mesh, const SurfaceContent& surface) {
  constexpr auto little = std::endian::little;
  std::string bytes;
  const auto flush = [&] {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    bytes.clear();
  };
  for (NodeIndex n : surface.nodes) {
    const Vec3 p = mesh.node(n);
    for (double c : {p.x, p.y, p.z}) appendRaw(bytes, c, little);
    if (bytes.size() >= (1u << 20)) flush();
  }
  for (const MshElementBlock& b : surface.blocks)
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      const auto nodes = b.block->element(i);
      appendRaw(bytes, static_cast<std::uint8_t>(nodes.size()), little);
      for (NodeIndex n : nodes)
        appendRaw(bytes, static_cast<std::int32_t>(surface.indexOfNode[n]), little);
      if (bytes.size() >= (1u << 20)) flush();
    }
  flush();
}

}  // namespace

// Named by the ply row of io/formats.cpp.
void writePly(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const SurfaceContent surface = selectSurfaceContent(model, mesh, options.saveAll, "ply");
  if (surface.nodes.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("ply files index vertices with 32-bit integers: " +
                                std::to_string(surface.nodes.size()) + " vertices are too many");
  writeHeader(out, surface, options.binary);
  if (options.binary)
    writeBinary(out, mesh, surface);
  else
    writeAsciiVerticesAndFaces(out, mesh, surface);
}

}  // namespace geomesh
