// buildCellComplex: from elements down to vertices, one dimension at a time, each level's
// cells found by sorting the faces the level above (and the elements of that dimension) hold.
#include "mesh/homology/cell_complex.h"

#include <algorithm>
#include <limits>

namespace geomesh {

namespace {

constexpr NodeIndex kNoNode = std::numeric_limits<NodeIndex>::max();
constexpr CellId kNoOwner = std::numeric_limits<CellId>::max();

// The faces of a volume element, each running round counter-clockwise seen from outside the
// element (for the numbering of the MSH format).
struct LocalFace {
  int count;
  std::array<int, 4> corner;
};
constexpr LocalFace kTetFaces[] = {{3, {0, 2, 1}}, {3, {0, 1, 3}}, {3, {0, 3, 2}}, {3, {1, 2, 3}}};
constexpr LocalFace kHexFaces[] = {{4, {0, 3, 2, 1}}, {4, {4, 5, 6, 7}}, {4, {0, 1, 5, 4}},
                                   {4, {1, 2, 6, 5}}, {4, {2, 3, 7, 6}}, {4, {3, 0, 4, 7}}};
constexpr LocalFace kPrismFaces[] = {
    {3, {0, 2, 1}}, {3, {3, 4, 5}}, {4, {0, 1, 4, 3}}, {4, {1, 2, 5, 4}}, {4, {2, 0, 3, 5}}};
constexpr LocalFace kPyramidFaces[] = {
    {4, {0, 3, 2, 1}}, {3, {0, 1, 4}}, {3, {1, 2, 4}}, {3, {2, 3, 4}}, {3, {3, 0, 4}}};

std::span<const LocalFace> volumeFaces(ElementFamily f) {
  switch (f) {
    case ElementFamily::Tet:
      return kTetFaces;
    case ElementFamily::Hex:
      return kHexFaces;
    case ElementFamily::Prism:
      return kPrismFaces;
    default:
      return kPyramidFaces;
  }
}

// Sorts the first n entries (n at most 8) by insertion.
template <std::size_t N>
void sortPrefix(std::array<NodeIndex, N>& a, std::size_t n) {
  for (std::size_t i = 1; i < n && i < N; ++i)
    for (std::size_t j = i; j > 0 && a[j] < a[j - 1]; --j) std::swap(a[j], a[j - 1]);
}

// Writes the cell's own orientation of `in` (see CellComplex) to `out` and returns +1 when
// `in` runs the same way, -1 otherwise. A polygon starts at its smallest node.
int orient(std::span<const NodeIndex> in, NodeIndex* out) {
  const std::size_t n = in.size();
  if (n == 1) {
    out[0] = in[0];
    return 1;
  }
  if (n == 2) {
    out[0] = std::min(in[0], in[1]);
    out[1] = std::max(in[0], in[1]);
    return in[0] < in[1] ? 1 : -1;
  }
  const std::size_t i = std::min_element(in.begin(), in.end()) - in.begin();
  const bool forward = in[(i + 1) % n] < in[(i + n - 1) % n];
  for (std::size_t j = 0; j < n; ++j) out[j] = forward ? in[(i + j) % n] : in[(i + n - j) % n];
  return forward ? 1 : -1;
}

// A cell of dimension 0 to 2 met while walking down: its nodes in the order met, the cell of
// the level above whose boundary holds it (kNoOwner for an element) and the factor its
// incidence there takes besides orientation (-1 for the start vertex of an edge).
struct Occurrence {
  std::array<NodeIndex, 4> key;  // sorted nodes, padded with kNoNode
  std::array<NodeIndex, 4> nodes;
  CellId owner;
  std::uint8_t count;
  std::int8_t factor;
};

struct OwnedIncidence {
  CellId owner, cell;
  std::int32_t sign;
};

// The cells of one dimension: sorted keys, oriented nodes (CSR), shapes, and the incidences
// of the cells of the level above into them (owner numbered in that level).
struct Level {
  std::vector<std::array<NodeIndex, 8>> keys;
  std::vector<NodeIndex> nodes;
  std::vector<std::uint32_t> nodeStart{0};
  std::vector<ElementFamily> family;
  std::vector<OwnedIncidence> incidences;

  std::span<const NodeIndex> cellNodes(std::size_t i) const {
    return {nodes.data() + nodeStart[i], nodes.data() + nodeStart[i + 1]};
  }
};

ElementFamily familyOf(int dim, int count) {
  if (dim == 0) return ElementFamily::Point;
  if (dim == 1) return ElementFamily::Line;
  return count == 3 ? ElementFamily::Triangle : ElementFamily::Quad;
}

Occurrence occurrence(std::span<const NodeIndex> nodes, CellId owner, int factor) {
  Occurrence o{};
  o.key.fill(kNoNode);
  o.nodes.fill(kNoNode);
  std::copy(nodes.begin(), nodes.end(), o.key.begin());
  std::copy(nodes.begin(), nodes.end(), o.nodes.begin());
  sortPrefix(o.key, nodes.size());
  o.owner = owner;
  o.count = static_cast<std::uint8_t>(nodes.size());
  o.factor = static_cast<std::int8_t>(factor);
  return o;
}

Level volumeLevel(std::span<const ComplexElement> elements) {
  std::vector<std::pair<std::array<NodeIndex, 8>, std::size_t>> sorted;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const ComplexElement& e = elements[i];
    if (dimension(e.family) != 3) continue;
    std::array<NodeIndex, 8> key;
    key.fill(kNoNode);
    const int n = vertexCount(e.family);
    std::copy(e.corners.begin(), e.corners.begin() + n, key.begin());
    sortPrefix(key, static_cast<std::size_t>(n));
    sorted.push_back({key, i});
  }
  std::sort(sorted.begin(), sorted.end());
  Level level;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (i > 0 && sorted[i].first == sorted[i - 1].first) continue;
    const ComplexElement& e = elements[sorted[i].second];
    level.keys.push_back(sorted[i].first);
    level.family.push_back(e.family);
    level.nodes.insert(level.nodes.end(), e.corners.begin(),
                       e.corners.begin() + vertexCount(e.family));
    level.nodeStart.push_back(static_cast<std::uint32_t>(level.nodes.size()));
  }
  return level;
}

// The faces of every cell of `above` (dimension dim + 1) and the elements of dimension dim.
std::vector<Occurrence> occurrencesBelow(const Level& above, int dim,
                                         std::span<const ComplexElement> elements) {
  std::vector<Occurrence> out;
  for (std::size_t c = 0; c < above.family.size(); ++c) {
    const auto nodes = above.cellNodes(c);
    const auto owner = static_cast<CellId>(c);
    if (dim == 2) {
      for (const LocalFace& f : volumeFaces(above.family[c])) {
        std::array<NodeIndex, 4> face{};
        for (int k = 0; k < f.count; ++k) face[k] = nodes[f.corner[k]];
        out.push_back(occurrence({face.data(), static_cast<std::size_t>(f.count)}, owner, 1));
      }
    } else if (dim == 1) {
      for (std::size_t k = 0; k < nodes.size(); ++k) {
        const NodeIndex edge[2] = {nodes[k], nodes[(k + 1) % nodes.size()]};
        out.push_back(occurrence(edge, owner, 1));
      }
    } else {
      out.push_back(occurrence(nodes.subspan(0, 1), owner, -1));
      out.push_back(occurrence(nodes.subspan(1, 1), owner, 1));
    }
  }
  for (const ComplexElement& e : elements)
    if (dimension(e.family) == dim)
      out.push_back(occurrence({e.corners.data(), static_cast<std::size_t>(vertexCount(e.family))},
                               kNoOwner, 1));
  return out;
}

Level levelBelow(const Level& above, int dim, std::span<const ComplexElement> elements) {
  std::vector<Occurrence> occ = occurrencesBelow(above, dim, elements);
  std::sort(occ.begin(), occ.end(), [](const Occurrence& a, const Occurrence& b) {
    for (int k = 0; k < 4; ++k)
      if (a.key[k] != b.key[k]) return a.key[k] < b.key[k];
    return a.owner < b.owner;
  });
  Level level;
  for (std::size_t i = 0; i < occ.size(); ++i) {
    const Occurrence& o = occ[i];
    const std::span<const NodeIndex> met(o.nodes.data(), o.count);
    if (i == 0 || o.key != occ[i - 1].key) {
      std::array<NodeIndex, 8> key;
      key.fill(kNoNode);
      std::copy(o.key.begin(), o.key.end(), key.begin());
      level.keys.push_back(key);
      level.family.push_back(familyOf(dim, o.count));
      const std::size_t start = level.nodes.size();
      level.nodes.resize(start + o.count);
      orient(met, level.nodes.data() + start);
      level.nodeStart.push_back(static_cast<std::uint32_t>(level.nodes.size()));
    }
    if (o.owner == kNoOwner) continue;
    const auto cell = static_cast<CellId>(level.keys.size() - 1);
    std::array<NodeIndex, 4> scratch{};
    const int sign = orient(met, scratch.data()) * o.factor;
    level.incidences.push_back({o.owner, cell, sign});
  }
  return level;
}

std::array<Level, 4> walkDown(std::span<const ComplexElement> elements) {
  std::array<Level, 4> levels;
  levels[3] = volumeLevel(elements);
  for (int dim = 2; dim >= 0; --dim) levels[dim] = levelBelow(levels[dim + 1], dim, elements);
  return levels;
}

}  // namespace

int CellComplex::dimension(CellId c) const {
  int dim = 0;
  while (dim < 3 && c >= first_[dim + 1]) ++dim;
  return dim;
}

int CellComplex::topDimension() const {
  for (int dim = 3; dim >= 0; --dim)
    if (count(dim) > 0) return dim;
  return -1;
}

// Assembles the complex from the levels of the domain, leaving out the cells the subdomain's
// levels hold.
class CellComplexBuilder {
 public:
  static CellComplex build(const std::array<Level, 4>& domain,
                           const std::array<Level, 4>& subdomain) {
    CellComplex complex;
    std::array<std::vector<CellId>, 4> id;  // per level: final id, or kNoOwner if left out
    CellId next = 0;
    for (int dim = 0; dim <= 3; ++dim) {
      complex.first_[dim] = next;
      const Level& level = domain[dim];
      const auto& excluded = subdomain[dim].keys;
      id[dim].assign(level.keys.size(), kNoOwner);
      for (std::size_t i = 0; i < level.keys.size(); ++i) {
        if (std::binary_search(excluded.begin(), excluded.end(), level.keys[i])) continue;
        id[dim][i] = next++;
        complex.family_.push_back(level.family[i]);
        const auto nodes = level.cellNodes(i);
        complex.nodes_.insert(complex.nodes_.end(), nodes.begin(), nodes.end());
        complex.nodeStart_.push_back(static_cast<std::uint32_t>(complex.nodes_.size()));
      }
    }
    complex.first_[4] = next;
    linkIncidences(complex, domain, id);
    return complex;
  }

 private:
  // Faces of each kept cell (those kept of its boundary), then cofaces by transposition.
  static void linkIncidences(CellComplex& complex, const std::array<Level, 4>& domain,
                             const std::array<std::vector<CellId>, 4>& id) {
    const std::size_t n = complex.size();
    std::vector<std::uint32_t> faceCount(n + 1, 0), cofaceCount(n + 1, 0);
    std::vector<std::pair<CellId, Incidence>> kept;  // (cell, face)
    for (int dim = 0; dim < 3; ++dim)
      for (const OwnedIncidence& inc : domain[dim].incidences) {
        const CellId owner = id[dim + 1][inc.owner], cell = id[dim][inc.cell];
        if (owner == kNoOwner || cell == kNoOwner) continue;
        kept.push_back({owner, {cell, inc.sign}});
        ++faceCount[owner + 1];
        ++cofaceCount[cell + 1];
      }
    for (std::size_t c = 0; c < n; ++c) {
      faceCount[c + 1] += faceCount[c];
      cofaceCount[c + 1] += cofaceCount[c];
    }
    complex.faceStart_ = faceCount;
    complex.cofaceStart_ = cofaceCount;
    complex.faces_.resize(kept.size());
    complex.cofaces_.resize(kept.size());
    for (const auto& [owner, face] : kept) {
      complex.faces_[faceCount[owner]++] = face;
      complex.cofaces_[cofaceCount[face.cell]++] = {owner, face.sign};
    }
  }
};

CellComplex buildCellComplex(std::span<const ComplexElement> domain,
                             std::span<const ComplexElement> subdomain) {
  return CellComplexBuilder::build(walkDown(domain), walkDown(subdomain));
}

}  // namespace geomesh
