// View files: reading post-processing data (list-based .pos files, the data sections of MSH
// files) and writing views (.pos in the parsed format, .msh with data sections).
#pragma once

#include <stdexcept>
#include <string>

#include "mesh/core/mesh.h"
#include "mesh/views/view.h"

namespace geomesh {

// A malformed view file: `what()` is "path:line:col: message" for text, "path: byte N:
// message" for binary data.
struct ViewReadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Whether a .pos file is in the list-based format ($PostFormat ... $View ... $EndView)
// rather than the parsed one (View "name" { ... };, read as a script).
bool isListBasedPosFile(const std::string& path);
// Appends the views of a list-based .pos file (ASCII or binary) to `views`; returns how many.
int readListBasedPos(const std::string& path, post::ViewStore& views);

// Appends a view for each data section ($NodeData, $ElementData, $ElementNodeData; MSH 4.1
// and 2.2, ASCII and binary) of an MSH file whose mesh is `mesh` (read from the same file):
// sections with the same name are the time steps of one view. Each view gets its element
// lists (coordinates from `mesh`) and its MeshData as the file gave it. Returns how many.
// MeshData tags are the mesh's own: node i has tag i + 1; elements are numbered from 1 over
// mesh.entities() in order, each entity's blocks and their elements in order. The file's
// tags are mapped onto them (nodes by their place in $Nodes, as readMsh adds them; elements
// by type and nodes); a file without $Nodes and $Elements uses them directly. Data on a
// node or element the mesh lacks is a ViewReadError at its line (or byte).
int readMshViews(const std::string& path, const Mesh& mesh, post::ViewStore& views);

// Rebuilds the element lists of a view with MeshData over `mesh`: every mesh element with
// values at each of its nodes in every step (complete second-order elements as order-2 lists,
// other high-order elements by their corners; 2 components padded to a vector, 6 made a full
// symmetric tensor).
void buildMeshDataLists(post::View& view, const Mesh& mesh);

// Writes one view: ".pos" in the parsed format (every element list, time steps and texts);
// ".msh" as MSH 4.1 (2.2 when `mshVersion` is 2.2) ASCII: a view with MeshData over `mesh`
// as that data (the mesh written with it), a list-based view as its own nodes and elements
// with $ElementNodeData. `append` adds to an existing .pos file, and to an existing .msh file
// (of the same mesh) the data sections of a view with MeshData. Throws std::runtime_error.
void writeView(const post::View& view, const std::string& path, const Mesh& mesh,
               double mshVersion = 4.1, bool append = false);

}  // namespace geomesh
