// HTML writer: one self-contained page that shows the mesh in a browser (WebGL), offline. It
// holds the mesh as a JSON block (io/mesh_page.h) and the viewer script (io/viewer_script.h);
// nothing is loaded from anywhere else.
#include <ostream>

#include "io/formats.h"
#include "io/mesh_page.h"
#include "io/viewer_script.h"

namespace geomesh {

void writeHtml(std::ostream& out, const Model& model, const Mesh& mesh,
               const MeshWriteOptions& options) {
  const MeshPage page = buildMeshPage(model, mesh, options.saveAll);
  out << "<!DOCTYPE html>\n"
         "<html lang=\"en\">\n"
         "<head>\n"
         "<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"geomesh\">\n"
         "<title>mesh - geomesh</title>\n"
         "</head>\n"
         "<body>\n"
         "<noscript>This page shows a mesh with JavaScript and WebGL: allow scripts to see "
         "it.</noscript>\n"
         "<script type=\"application/json\" id=\"geomesh-mesh\">"
      << meshPageJson(page)
      << "</script>\n"
         "<script>"
      << viewerScript()
      << "</script>\n"
         "</body>\n"
         "</html>\n";
}

}  // namespace geomesh
