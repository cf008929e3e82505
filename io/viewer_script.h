// viewerScript: the mesh viewer's JavaScript (viewer/src bundled with three.js), which every
// HTML page of a mesh carries. Its definition is generated at build time (cmake/Viewer.cmake).
#pragma once

#include <string>

namespace geomesh {

// The minified script, safe inside a <script> element (it holds no "</script").
const std::string& viewerScript();

}  // namespace geomesh
