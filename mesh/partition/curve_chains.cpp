// splitIntoChains: union-find over lines sharing an inner node, then a walk along each group.
#include "mesh/partition/curve_chains.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace geomesh {

namespace {

std::size_t findRoot(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The lines of one group in walking order, each turned so that its first corner is where the
// walk arrives.
ElementBlock walk(const ElementBlock& block, const std::vector<std::size_t>& lines) {
  std::map<NodeIndex, std::vector<std::size_t>> around;  // corner -> lines
  for (std::size_t l : lines)
    for (int c = 0; c < 2; ++c) around[block.element(l)[c]].push_back(l);
  std::vector<char> used(block.size(), 0);
  ElementBlock chain{block.type, {}};
  std::size_t left = lines.size();
  while (left > 0) {
    // Start at an end of the chain when it has one, else at its lowest unused line.
    std::size_t first =
        *std::find_if(lines.begin(), lines.end(), [&](std::size_t l) { return !used[l]; });
    NodeIndex at = block.element(first)[0];
    for (const auto& [node, touching] : around) {
      const auto unused =
          std::count_if(touching.begin(), touching.end(), [&](std::size_t l) { return !used[l]; });
      if (unused == 1 && touching.size() == 1) {
        at = node;
        first = touching.front();
        break;
      }
    }
    for (std::size_t line = first; line != block.size();) {
      used[line] = 1;
      --left;
      std::vector<NodeIndex> nodes(block.element(line).begin(), block.element(line).end());
      if (nodes[0] != at) std::swap(nodes[0], nodes[1]);
      // High-order nodes between the corners run from the first corner: reversed with it.
      if (nodes.size() > 2 && block.element(line)[0] != nodes[0])
        std::reverse(nodes.begin() + 2, nodes.end());
      chain.nodes.insert(chain.nodes.end(), nodes.begin(), nodes.end());
      at = nodes[1];
      line = block.size();
      for (std::size_t next : around[at])
        if (!used[next]) line = next;
    }
  }
  return chain;
}

}  // namespace

std::vector<ElementBlock> splitIntoChains(const ElementBlock& block,
                                          const std::function<bool(NodeIndex)>& joins,
                                          bool walkThem) {
  std::vector<std::size_t> parent(block.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::map<NodeIndex, std::size_t> lineAt;  // inner corner -> a line through it
  for (std::size_t l = 0; l < block.size(); ++l)
    for (int c = 0; c < 2; ++c) {
      const NodeIndex n = block.element(l)[c];
      if (!joins(n)) continue;
      const auto [it, added] = lineAt.emplace(n, l);
      if (!added) parent[findRoot(parent, l)] = findRoot(parent, it->second);
    }
  std::map<std::size_t, std::vector<std::size_t>> groups;  // by lowest line, in order
  std::vector<std::size_t> lowest(block.size(), block.size());
  for (std::size_t l = 0; l < block.size(); ++l) {
    const std::size_t root = findRoot(parent, l);
    if (lowest[root] == block.size()) lowest[root] = l;
    groups[lowest[root]].push_back(l);
  }
  std::vector<ElementBlock> chains;
  for (const auto& [first, lines] : groups) {
    if (walkThem) {
      chains.push_back(walk(block, lines));
      continue;
    }
    ElementBlock kept{block.type, {}};
    for (std::size_t l : lines)
      kept.nodes.insert(kept.nodes.end(), block.element(l).begin(), block.element(l).end());
    chains.push_back(std::move(kept));
  }
  return chains;
}

bool orderAlongCurve(ElementBlock& block, NodeIndex start) {
  std::map<NodeIndex, std::size_t> leaving;  // first corner -> line
  for (std::size_t l = 0; l < block.size(); ++l)
    if (!leaving.emplace(block.element(l)[0], l).second) return false;
  ElementBlock ordered{block.type, {}};
  NodeIndex at = start;
  for (std::size_t k = 0; k < block.size(); ++k) {
    const auto it = leaving.find(at);
    if (it == leaving.end()) return false;
    const auto line = block.element(it->second);
    ordered.nodes.insert(ordered.nodes.end(), line.begin(), line.end());
    at = line[1];
    leaving.erase(it);
  }
  block = std::move(ordered);
  return true;
}

}  // namespace geomesh
