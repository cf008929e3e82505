// OFF writer (Object File Format, ASCII): the surface triangles and quadrangles of a mesh as
// faces over the vertices they use.
#include <ostream>

#include "io/formats.h"
#include "io/surface_content.h"

namespace geomesh {

// Named by the off row of io/formats.cpp.
void writeOff(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const SurfaceContent surface = selectSurfaceContent(model, mesh, options.saveAll, "off");
  out << "OFF\n" << surface.nodes.size() << ' ' << surface.faceCount << " 0\n";
  writeAsciiVerticesAndFaces(out, mesh, surface);
}

}  // namespace geomesh
