// maximumMatching by LEMON's maximum-cardinality matching, compiled as C++17.
#include "mesh/quads/blossom_matching.h"

#include <lemon/matching.h>
#include <lemon/smart_graph.h>

namespace geomesh {

std::vector<std::uint8_t> maximumMatching(std::uint32_t nodeCount,
                                          const std::vector<std::uint32_t>& ends,
                                          const std::vector<std::uint8_t>& initial) {
  using Graph = lemon::SmartGraph;
  Graph graph;
  const std::size_t edgeCount = ends.size() / 2;
  graph.reserveNode(static_cast<int>(nodeCount));
  graph.reserveEdge(static_cast<int>(edgeCount));
  std::vector<Graph::Node> nodes;
  nodes.reserve(nodeCount);
  for (std::uint32_t k = 0; k < nodeCount; ++k) nodes.push_back(graph.addNode());
  std::vector<Graph::Edge> edges;
  edges.reserve(edgeCount);
  for (std::size_t e = 0; e < edgeCount; ++e)
    edges.push_back(graph.addEdge(nodes[ends[2 * e]], nodes[ends[2 * e + 1]]));
  Graph::EdgeMap<bool> start(graph, false);
  for (std::size_t e = 0; e < edgeCount; ++e) start[edges[e]] = initial[e] != 0;
  lemon::MaxMatching<Graph> matching(graph);
  if (!matching.matchingInit(start)) matching.greedyInit();
  matching.startSparse();
  std::vector<std::uint8_t> matched(edgeCount, 0);
  for (std::size_t e = 0; e < edgeCount; ++e) matched[e] = matching.matching(edges[e]) ? 1 : 0;
  return matched;
}

}  // namespace geomesh
