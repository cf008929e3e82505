// What the formats of surface meshes (STL, PLY, OFF, OBJ) save: the linear triangles and
// quadrangles of what an MSH file would save, and the nodes they use.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "io/msh_content.h"

namespace geomesh {

struct SurfaceContent {
  MshContent content;                        // everything an MSH file would save
  std::vector<MshElementBlock> blocks;       // its Triangle3 and Quad4 blocks, in its order
  std::vector<NodeIndex> nodes;              // the nodes they use, in the order of their tags
  std::vector<std::uint32_t> indexOfNode;    // per mesh node: its index in `nodes`
  std::size_t faceCount = 0;                 // triangles and quadrangles
};

// Points, lines and volume elements are left out. Throws std::invalid_argument naming `format`
// ("stl") when a surface element is above order 1, or when there are elements but none on a
// surface ("stl files hold surface elements only: the mesh to save has 1200 hexahedron elements
// and no surface element").
SurfaceContent selectSurfaceContent(const Model& model, const Mesh& mesh, bool saveAll,
                                    std::string_view format);

// The faces in named parts, as STL solids and OBJ objects hold them: with only physical groups
// saved, one part per physical surface, named by physicalGroupName (the group's name, else
// "PhysicalSurface3") and holding the blocks of the group's entities; otherwise one part per
// surface entity ("surface3").
struct NamedSurfacePart {
  std::string name;
  std::vector<const ElementBlock*> blocks;
};
std::vector<NamedSurfacePart> namedSurfaceParts(const Model& model,
                                                const SurfaceContent& surface);

// The vertex lines ("x y z") then the face lines ("3 i j k", indices into `nodes`), as the
// ASCII forms of PLY and OFF both lay them out.
void writeAsciiVerticesAndFaces(std::ostream& out, const Mesh& mesh,
                                const SurfaceContent& surface);

}  // namespace geomesh
