// METIS on the dual graph of the top-dimensional elements, and the slicing partitioner.
#include "mesh/partition/element_partition.h"

#include <metis.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mesh/partition/partition_sets.h"

namespace geomesh {

TopElements topElements(const Mesh& mesh) {
  TopElements top;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks)
      if (b.size() > 0) top.dim = std::max(top.dim, dimension(b.type));
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks)
      if (dimension(b.type) == top.dim)
        for (std::size_t i = 0; i < b.size(); ++i) top.elements.push_back({&b, i});
  return top;
}

namespace {

// The dual graph in METIS's compressed rows: elements are adjacent when they share a facet.
// Facets are found by sorting them, not by METIS_MeshToDual's search through common nodes,
// which costs several times more on large meshes.
struct DualGraph {
  std::vector<idx_t> xadj, adjncy;
};

DualGraph dualGraph(const TopElements& top) {
  struct Side {
    FacetKey key;
    idx_t element;
  };
  std::vector<Side> sides;
  for (std::size_t e = 0; e < top.elements.size(); ++e) {
    const TopElements::Ref& r = top.elements[e];
    const auto nodes = r.block->element(r.index);
    for (const std::vector<int>& facet : facetsOf(family(r.block->type))) {
      std::array<NodeIndex, 4> corners{};
      for (std::size_t k = 0; k < facet.size(); ++k) corners[k] = nodes[facet[k]];
      sides.push_back({facetKey(std::span(corners.data(), facet.size())), static_cast<idx_t>(e)});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return a.key != b.key ? a.key < b.key : a.element < b.element;
  });
  std::vector<std::pair<idx_t, idx_t>> edges;
  for (std::size_t i = 0; i + 1 < sides.size(); ++i)
    if (sides[i].key == sides[i + 1].key && sides[i].element != sides[i + 1].element) {
      edges.emplace_back(sides[i].element, sides[i + 1].element);
      edges.emplace_back(sides[i + 1].element, sides[i].element);
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  DualGraph graph;
  graph.xadj.assign(top.elements.size() + 1, 0);
  for (const auto& [a, b] : edges) ++graph.xadj[a + 1];
  for (std::size_t e = 0; e < top.elements.size(); ++e) graph.xadj[e + 1] += graph.xadj[e];
  for (const auto& [a, b] : edges) graph.adjncy.push_back(b);
  return graph;
}

std::vector<idx_t> loadWeights(const TopElements& top, const MetisSettings& settings) {
  std::vector<idx_t> weights;
  if (std::all_of(settings.familyWeights.begin(), settings.familyWeights.end(),
                  [](int w) { return w <= 0; }))
    return weights;
  for (const TopElements::Ref& r : top.elements) {
    const int w = settings.familyWeights[static_cast<int>(family(r.block->type))];
    weights.push_back(w > 0 ? w : 1);
  }
  return weights;
}

void setOptions(idx_t* options, const MetisSettings& settings) {
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_CTYPE] = settings.edgeMatching == 1 ? METIS_CTYPE_RM : METIS_CTYPE_SHEM;
  static constexpr idx_t kRefinement[] = {METIS_RTYPE_FM, METIS_RTYPE_GREEDY, METIS_RTYPE_SEP2SIDED,
                                          METIS_RTYPE_SEP1SIDED};
  if (settings.refinement >= 1 && settings.refinement <= 4)
    options[METIS_OPTION_RTYPE] = kRefinement[settings.refinement - 1];
  // Mesh.MetisMaxLoadImbalance is METIS's ufactor: 30 allows 3%.
  if (settings.maxImbalance >= 0)
    options[METIS_OPTION_UFACTOR] = std::lround(settings.maxImbalance);
  if (settings.algorithm == 2) {
    options[METIS_OPTION_OBJTYPE] = settings.objective == 2 ? METIS_OBJTYPE_VOL : METIS_OBJTYPE_CUT;
    if (settings.minConnectivity >= 0) options[METIS_OPTION_MINCONN] = settings.minConnectivity;
  }
  options[METIS_OPTION_NUMBERING] = 0;
}

}  // namespace

std::vector<int> metisPartition(const TopElements& top, int count, const MetisSettings& settings) {
  const std::size_t n = top.elements.size();
  if (count < 1) throw std::invalid_argument("the number of partitions must be at least 1");
  if (static_cast<std::size_t>(count) > n)
    throw std::invalid_argument("cannot make " + std::to_string(count) + " partitions of " +
                                std::to_string(n) + " element(s)");
  if (count == 1) return std::vector<int>(n, 1);
  DualGraph graph = dualGraph(top);
  if (graph.adjncy.empty()) graph.adjncy.push_back(0);  // METIS wants an array even when empty
  std::vector<idx_t> weights = loadWeights(top, settings);
  idx_t options[METIS_NOPTIONS];
  setOptions(options, settings);
  idx_t vertices = static_cast<idx_t>(n), constraints = 1, parts = count, cut = 0;
  std::vector<idx_t> part(n);
  const auto run = settings.algorithm == 2 ? METIS_PartGraphKway : METIS_PartGraphRecursive;
  const int status = run(&vertices, &constraints, graph.xadj.data(), graph.adjncy.data(),
                         weights.empty() ? nullptr : weights.data(), nullptr, nullptr, &parts,
                         nullptr, nullptr, options, &cut, part.data());
  if (status != METIS_OK)
    throw std::runtime_error("METIS failed to partition the mesh (status " +
                             std::to_string(status) + ")");
  std::vector<int> result(n);
  for (std::size_t i = 0; i < n; ++i) result[i] = static_cast<int>(part[i]) + 1;
  return result;
}

namespace {

Vec3 centroid(const Mesh& mesh, const TopElements::Ref& r) {
  const auto element = r.block->element(r.index);
  const int corners = vertexCount(r.block->type);
  Vec3 c{};
  for (int k = 0; k < corners; ++k) {
    const Vec3 p = mesh.node(element[k]);
    c = {c.x + p.x / corners, c.y + p.y / corners, c.z + p.z / corners};
  }
  return c;
}

int sliceOf(double v, double lo, double hi, int slices) {
  if (slices <= 1 || hi <= lo) return 0;
  return std::clamp(static_cast<int>((v - lo) / (hi - lo) * slices), 0, slices - 1);
}

}  // namespace

std::vector<int> slicePartition(const Mesh& mesh, const TopElements& top,
                                std::array<int, 3> slices) {
  for (int& s : slices) s = std::max(1, s);
  std::vector<Vec3> centres;
  BoundingBox box;
  for (const TopElements::Ref& r : top.elements) {
    centres.push_back(centroid(mesh, r));
    box.include(centres.back());
  }
  std::vector<int> result;
  for (const Vec3& c : centres) {
    const int i = sliceOf(c.x, box.min.x, box.max.x, slices[0]);
    const int j = sliceOf(c.y, box.min.y, box.max.y, slices[1]);
    const int k = sliceOf(c.z, box.min.z, box.max.z, slices[2]);
    result.push_back(1 + i + slices[0] * (j + slices[1] * k));
  }
  return result;
}

}  // namespace geomesh
