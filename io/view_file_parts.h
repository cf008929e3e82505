// What the view file readers and writers share: loading a file, the element shapes of views
// as MSH element types, and the writers of each format behind writeView.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "mesh/core/element_type.h"
#include "mesh/core/mesh.h"
#include "mesh/views/view.h"

namespace geomesh {

// The bytes of a file; ViewReadError "cannot open '<path>'" if it cannot be read.
std::string readViewFile(const std::string& path);

// Nodes of an element of a view list: corners for order 1; corners, then edge, face and
// volume nodes (the complete Lagrange element) for order 2.
int listNodeCount(post::ElementShape shape, int order);
// The MSH element type of a view list's elements (order 1 or 2).
ElementType listElementType(post::ElementShape shape, int order);
// The view shape of an MSH element type, and the order a view list can hold it with: 2 for
// the complete second-order types, 1 (corners only) for every other type.
post::ElementShape shapeOfType(ElementType type);
int listOrderOfType(ElementType type);

// A view in the parsed .pos format: View "name" { TIME{...}; ST(...){...}; ... T2(...){...}; };
void writeParsedPos(std::ostream& out, const post::View& view);
// A view as MSH (4.1 or 2.2, ASCII): the mesh and the view's MeshData over it (only the data
// sections with `dataOnly`, to follow the same mesh written before), or for a list-based view
// its own nodes and elements with $ElementNodeData.
void writeMshView(std::ostream& out, const post::View& view, const Mesh& mesh, double version,
                  bool dataOnly = false);

}  // namespace geomesh
