// PolygonFaces: the faces of polygon files (PLY, OFF) as triangles and quadrangles of one
// discrete surface.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "io/mesh_scanner.h"
#include "mesh/core/mesh.h"

namespace geomesh {

class PolygonFaces {
 public:
  PolygonFaces(const MeshScanner& in, std::size_t nodeCount) : in_(in), nodeCount_(nodeCount) {}

  // Face number `face` (from 0) with these vertex indices (from 0); fails for a face of other
  // than 3 or 4 vertices, or a vertex the file does not have.
  void add(std::span<const std::int64_t> vertices, std::uint64_t face) {
    if (vertices.size() != 3 && vertices.size() != 4)
      in_.fail("face " + std::to_string(face) + " has " + std::to_string(vertices.size()) +
               " vertices: triangles and quadrangles are read");
    ElementBlock& block = vertices.size() == 3 ? triangles_ : quads_;
    for (std::int64_t v : vertices) {
      if (v < 0 || static_cast<std::uint64_t>(v) >= nodeCount_)
        in_.fail("face " + std::to_string(face) + " uses vertex " + std::to_string(v) +
                 ", but the file has " + std::to_string(nodeCount_) + " vertices");
      block.nodes.push_back(static_cast<NodeIndex>(v));
    }
  }

  // The faces go to surface 1 of `mesh`.
  void moveInto(Mesh& mesh) {
    for (ElementBlock* block : {&triangles_, &quads_})
      if (block->size() > 0) mesh.entity({2, 1}).block(block->type) = std::move(*block);
  }

 private:
  const MeshScanner& in_;
  std::size_t nodeCount_;
  ElementBlock triangles_{ElementType::Triangle3, {}};
  ElementBlock quads_{ElementType::Quad4, {}};
};

}  // namespace geomesh
