// buildMeshPage: the elements, groups, quality and volume-face neighbours a mesh's page shows.
#include "io/mesh_page.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

#include "io/msh_content.h"
#include "mesh/core/quality.h"
#include "mesh/partition/partition_sets.h"

namespace geomesh {

namespace {

constexpr std::uint32_t kNoNode = std::numeric_limits<std::uint32_t>::max();

// The blocks of dimension 1 to 3 that a mesh file would save, each with the id of its first
// element; points are numbered too, so that ids stay those of the file.
struct ShownBlock {
  EntityId entity;
  const ElementBlock* block;
  std::size_t firstId;
};

std::vector<ShownBlock> shownBlocks(const MshContent& content) {
  std::vector<ShownBlock> shown;
  std::size_t nextId = 1;
  for (const MshElementBlock& b : content.elementBlocks) {
    if (dimension(b.block->type) >= 1) shown.push_back({b.entity, b.block, nextId});
    nextId += b.block->size();
  }
  return shown;
}

// Page nodes: the corners the shown elements use, in the mesh's node order.
void numberNodes(const Mesh& mesh, const std::vector<ShownBlock>& shown, MeshPage& page,
                 std::vector<std::uint32_t>& pageNode) {
  pageNode.assign(mesh.nodeCount(), kNoNode);
  std::vector<char> used(mesh.nodeCount(), 0);
  for (const ShownBlock& s : shown) {
    const int k = vertexCount(s.block->type);
    for (std::size_t i = 0; i < s.block->size(); ++i)
      for (int c = 0; c < k; ++c) used[s.block->element(i)[c]] = 1;
  }
  BoundingBox box;
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) {
    if (!used[n]) continue;
    pageNode[n] = static_cast<std::uint32_t>(page.meshNodes.size());
    page.meshNodes.push_back(n);
    box.include(mesh.node(n));
  }
  page.origin = 0.5 * (box.min + box.max);
  page.coordinates.reserve(3 * page.meshNodes.size());
  for (NodeIndex n : page.meshNodes) {
    const Vec3 p = mesh.node(n) - page.origin;
    page.coordinates.insert(
        page.coordinates.end(),
        {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
  }
}

// Volumes first, then surfaces, then curves; by tag within a dimension.
bool listedBefore(EntityId a, EntityId b) {
  return a.dim != b.dim ? a.dim > b.dim : a.tag < b.tag;
}

// The physical groups (of dimension 1 to 3) that hold a shown entity, then one group per
// shown entity that none holds. Returns each entity's groups.
std::map<EntityId, std::vector<int>> listGroups(const Model& model,
                                                const std::vector<ShownBlock>& shown,
                                                MeshPage& page) {
  std::set<EntityId> entities;
  for (const ShownBlock& s : shown) entities.insert(s.entity);
  std::vector<const PhysicalGroup*> physicals;
  for (const auto& [id, group] : model.physicalGroups())
    if (group.dim >= 1) physicals.push_back(&group);
  std::stable_sort(physicals.begin(), physicals.end(), [](auto* a, auto* b) {
    return listedBefore({a->dim, a->tag}, {b->dim, b->tag});
  });
  std::map<EntityId, std::vector<int>> groupsOf;
  for (const PhysicalGroup* group : physicals) {
    const int index = static_cast<int>(page.groups.size());
    bool holdsShown = false;
    for (int tag : group->entities)
      if (entities.contains({group->dim, tag})) {
        groupsOf[{group->dim, tag}].push_back(index);
        holdsShown = true;
      }
    if (holdsShown) page.groups.push_back({group->name, group->dim, group->tag, true});
  }
  std::vector<EntityId> alone;
  for (EntityId e : entities)
    if (!groupsOf.contains(e)) alone.push_back(e);
  std::sort(alone.begin(), alone.end(), listedBefore);
  for (EntityId e : alone) {
    groupsOf[e].push_back(static_cast<int>(page.groups.size()));
    page.groups.push_back({"", e.dim, e.tag, false});
  }
  return groupsOf;
}

void measureQuality(const Mesh& mesh, const ElementBlock& block, PageBlock& out) {
  const ElementFamily f = family(block.type);
  if (dimension(f) < 2) return;
  const int k = vertexCount(f);
  out.gamma.reserve(block.size());
  out.sicn.reserve(block.size());
  for (std::size_t i = 0; i < block.size(); ++i) {
    std::array<Vec3, 8> v;
    for (int c = 0; c < k; ++c) v[c] = mesh.node(block.element(i)[c]);
    const std::span<const Vec3> corners(v.data(), k);
    out.gamma.push_back(
        static_cast<float>(elementQuality(block.type, corners, QualityMeasure::Gamma)));
    out.sicn.push_back(
        static_cast<float>(elementQuality(block.type, corners, QualityMeasure::Sicn)));
  }
}

// A face of a volume element: its corners sorted (kNoNode last for triangles), and where its
// neighbour's id goes.
struct FaceRecord {
  std::array<std::uint32_t, 4> key;
  std::uint32_t id;
  std::size_t block, slot;
};

void findNeighbours(MeshPage& page) {
  std::vector<FaceRecord> faces;
  for (std::size_t b = 0; b < page.blocks.size(); ++b) {
    PageBlock& block = page.blocks[b];
    const ElementFamily f = family(block.type);
    if (dimension(f) != 3) continue;
    const auto& local = volumeFaces(f);
    const int k = vertexCount(f);
    block.neighbours.assign(block.size() * local.size(), 0);
    for (std::size_t i = 0; i < block.size(); ++i)
      for (std::size_t j = 0; j < local.size(); ++j) {
        FaceRecord face{{kNoNode, kNoNode, kNoNode, kNoNode},
                        static_cast<std::uint32_t>(block.firstId + i),
                        b,
                        i * local.size() + j};
        for (std::size_t c = 0; c < local[j].size(); ++c)
          face.key[c] = block.corners[i * k + local[j][c]];
        std::sort(face.key.begin(), face.key.end());
        faces.push_back(face);
      }
  }
  std::sort(faces.begin(), faces.end(), [](const FaceRecord& a, const FaceRecord& b) {
    return a.key != b.key ? a.key < b.key : a.id < b.id;
  });
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j - i == 2) {  // a face of three or more elements is no interior face: both drawn
      page.blocks[faces[i].block].neighbours[faces[i].slot] = faces[i + 1].id;
      page.blocks[faces[i + 1].block].neighbours[faces[i + 1].slot] = faces[i].id;
    }
    i = j;
  }
}

}  // namespace

const std::vector<std::vector<int>>& volumeFaces(ElementFamily family) {
  static const std::vector<std::vector<int>> none;
  return dimension(family) == 3 ? facetsOf(family) : none;
}

NodePlaces familyEdges(ElementFamily family) {
  switch (family) {
    case ElementFamily::Line:
      return {{0, 1}};
    case ElementFamily::Triangle:
      return triangleEdges();
    case ElementFamily::Quad:
      return quadEdges();
    case ElementFamily::Tet:
      return tetEdges();
    case ElementFamily::Hex:
      return hexEdgesBottomTopVertical();
    case ElementFamily::Prism:
      return prismEdgesBottomTopVertical();
    case ElementFamily::Pyramid:
      return pyramidEdges();
    default:
      return {};
  }
}

MeshPage buildMeshPage(const Model& model, const Mesh& mesh, bool saveAll) {
  const MshContent content = selectMshContent(model, mesh, saveAll);
  const std::vector<ShownBlock> shown = shownBlocks(content);
  if (shown.empty())
    throw std::invalid_argument(
        std::string("nothing to show: the mesh has no line, surface or volume element") +
        (content.physicalOnly ? " in a physical group" : ""));
  MeshPage page;
  std::vector<std::uint32_t> pageNode;
  numberNodes(mesh, shown, page, pageNode);
  const std::map<EntityId, std::vector<int>> groupsOf = listGroups(model, shown, page);
  std::map<int, std::size_t> counts;
  for (const ShownBlock& s : shown) {
    PageBlock block{s.entity, s.block->type, s.firstId, {}, groupsOf.at(s.entity), {}, {}, {}};
    const int k = vertexCount(s.block->type);
    block.corners.reserve(k * s.block->size());
    for (std::size_t i = 0; i < s.block->size(); ++i)
      for (int c = 0; c < k; ++c) block.corners.push_back(pageNode[s.block->element(i)[c]]);
    measureQuality(mesh, *s.block, block);
    counts[static_cast<int>(s.block->type)] += s.block->size();
    page.blocks.push_back(std::move(block));
  }
  findNeighbours(page);
  for (const auto& [type, count] : counts)
    page.counts.emplace_back(elementName(static_cast<ElementType>(type)), count);
  return page;
}

}  // namespace geomesh
