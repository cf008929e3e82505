// Wavefront OBJ writer (ASCII): the surface triangles and quadrangles of a mesh. The vertices
// they use come first, each once, in the fewest digits that read back to the same coordinates;
// then an `o` statement per part, named as STL solids are (a physical surface by its group or,
// without groups or with Mesh.SaveAll, a surface entity as "surface3"), and its faces, whose
// vertex indices count from 1.
#include <cstdint>
#include <ostream>

#include "io/formats.h"
#include "io/real_text.h"
#include "io/surface_content.h"

namespace geomesh {

namespace {

void writeVertices(std::ostream& out, const Mesh& mesh, const SurfaceContent& surface) {
  for (NodeIndex n : surface.nodes) {
    const Vec3 p = mesh.node(n);
    out << 'v';
    for (double c : {p.x, p.y, p.z}) {
      out << ' ';
      writeShortestReal(out, c);
    }
    out << '\n';
  }
}

void writeFaces(std::ostream& out, const ElementBlock& block, const SurfaceContent& surface) {
  for (std::size_t i = 0; i < block.size(); ++i) {
    out << 'f';
    for (NodeIndex n : block.element(i)) out << ' ' << surface.indexOfNode[n] + std::uint64_t{1};
    out << '\n';
  }
}

}  // namespace

// Named by the obj row of io/formats.cpp.
void writeObj(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const SurfaceContent surface = selectSurfaceContent(model, mesh, options.saveAll, "obj");
  out << "# geomesh mesh\n";
  writeVertices(out, mesh, surface);
  for (const NamedSurfacePart& part : namedSurfaceParts(model, surface)) {
    out << "o " << part.name << '\n';
    for (const ElementBlock* block : part.blocks) writeFaces(out, *block, surface);
  }
}

}  // namespace geomesh
