// MeshPage: what the HTML page of a mesh shows, gathered from a model and its mesh: corner
// nodes, element blocks with their groups, per-element quality, and across which face each
// volume element meets another.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/node_order.h"
#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// A checkbox of the page: a physical group, or an entity that no physical group holds.
struct PageGroup {
  std::string name;  // empty for entities and unnamed groups
  int dim = 0;
  int tag = 0;
  bool physical = false;
};

// The elements of one type on one entity, by their corners (the first vertexCount nodes).
struct PageBlock {
  EntityId entity;
  ElementType type = ElementType::Triangle3;
  std::size_t firstId = 1;             // element ids as a mesh file numbers them
  std::vector<std::uint32_t> corners;  // page node indices, vertexCount(type) per element
  std::vector<int> groups;             // indices into MeshPage::groups; never empty
  // Surfaces and volumes: gamma and SICN for triangles and tetrahedra, the corners' scaled
  // Jacobian (both) for the other shapes. Empty for lines.
  std::vector<float> gamma, sicn;
  // Volumes: per element and face (volumeFaces order), the id of the element across it, 0
  // when none is.
  std::vector<std::uint32_t> neighbours;

  std::size_t size() const { return corners.size() / vertexCount(type); }
};

struct MeshPage {
  Vec3 origin;                       // the centre of the nodes' box
  std::vector<float> coordinates;    // per page node: x, y, z less `origin`
  std::vector<NodeIndex> meshNodes;  // per page node: its node in the mesh
  std::vector<PageGroup> groups;
  std::vector<PageBlock> blocks;  // of dimension 1 to 3, in the order of a mesh file
  std::vector<std::pair<std::string, std::size_t>> counts;  // per element type name
};

// The faces of a volume family as corner lists (3 or 4, outward for a valid element: those of
// facetsOf), and the edges of any family as corner pairs.
const std::vector<std::vector<int>>& volumeFaces(ElementFamily family);
NodePlaces familyEdges(ElementFamily family);

// The elements a mesh file would save (only those of physical groups when any exist, unless
// saveAll), points left out. Throws std::invalid_argument when none is left to show.
MeshPage buildMeshPage(const Model& model, const Mesh& mesh, bool saveAll);

// The page's data block: JSON with the arrays as little-endian base64.
std::string meshPageJson(const MeshPage& page);

}  // namespace geomesh
