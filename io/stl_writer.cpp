// STL writer: the surface triangles of a mesh (each quadrangle split in two along its 0-2
// diagonal), with each facet's normal computed from its vertices (right-hand rule). ASCII files
// hold one solid per physical surface (named by the group) or, without groups or with
// Mesh.SaveAll, one per surface entity ("surface3"); binary files (Mesh.Binary) hold a single
// unnamed solid, as the binary layout has no place for names: an 80-byte header, a facet count
// and 50 bytes per facet, little-endian.
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>

#include "io/binary_output.h"
#include "io/formats.h"
#include "io/real_text.h"
#include "io/surface_content.h"

namespace geomesh {

namespace {

using Triangle = std::array<Vec3, 3>;

// Calls `facet` with each triangle of the block's elements.
template <class Facet>
void forEachTriangle(const Mesh& mesh, const ElementBlock& block, Facet facet) {
  for (std::size_t i = 0; i < block.size(); ++i) {
    const auto n = block.element(i);
    facet(Triangle{mesh.node(n[0]), mesh.node(n[1]), mesh.node(n[2])});
    if (block.type == ElementType::Quad4)
      facet(Triangle{mesh.node(n[0]), mesh.node(n[2]), mesh.node(n[3])});
  }
}

Vec3 normalOf(const Triangle& t) { return normalized(cross(t[1] - t[0], t[2] - t[0])); }

void writeVector(std::ostream& out, const char* keyword, Vec3 v) {
  out << keyword;
  for (double c : {v.x, v.y, v.z}) {
    out << ' ';
    writeShortestReal(out, c);
  }
  out << '\n';
}

void writeAscii(std::ostream& out, const Mesh& mesh, const std::vector<NamedSurfacePart>& solids) {
  if (solids.empty()) out << "solid geomesh\nendsolid geomesh\n";
  for (const NamedSurfacePart& solid : solids) {
    out << "solid " << solid.name << '\n';
    for (const ElementBlock* block : solid.blocks)
      forEachTriangle(mesh, *block, [&](const Triangle& t) {
        writeVector(out, "facet normal", normalOf(t));
        out << "outer loop\n";
        for (const Vec3& p : t) writeVector(out, "vertex", p);
        out << "endloop\nendfacet\n";
      });
    out << "endsolid " << solid.name << '\n';
  }
}

void writeBinary(std::ostream& out, const Mesh& mesh, const std::vector<NamedSurfacePart>& solids) {
  std::uint64_t triangles = 0;
  for (const NamedSurfacePart& solid : solids)
    for (const ElementBlock* block : solid.blocks)
      triangles += block->size() * (block->type == ElementType::Quad4 ? 2 : 1);
  if (triangles > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("binary stl files hold at most 2^32 - 1 triangles, not " +
                                std::to_string(triangles));
  std::string bytes = "geomesh binary STL";
  bytes.resize(80, ' ');
  appendRaw(bytes, static_cast<std::uint32_t>(triangles), std::endian::little);
  const auto add = [&](Vec3 v) {
    for (double c : {v.x, v.y, v.z}) appendRaw(bytes, static_cast<float>(c), std::endian::little);
  };
  for (const NamedSurfacePart& solid : solids)
    for (const ElementBlock* block : solid.blocks)
      forEachTriangle(mesh, *block, [&](const Triangle& t) {
        add(normalOf(t));
        for (const Vec3& p : t) add(p);
        appendRaw(bytes, std::uint16_t{0}, std::endian::little);
        if (bytes.size() >= (1u << 20)) {
          out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
          bytes.clear();
        }
      });
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

// Named by the stl row of io/formats.cpp.
void writeStl(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const SurfaceContent surface = selectSurfaceContent(model, mesh, options.saveAll, "stl");
  const std::vector<NamedSurfacePart> solids = namedSurfaceParts(model, surface);
  if (options.binary)
    writeBinary(out, mesh, solids);
  else
    writeAscii(out, mesh, solids);
}

}  // namespace geomesh
