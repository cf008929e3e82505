#include "mesh/blossom_matching.h"

#include <lemon/matching.h>
#include <lemon/smart_graph.h>

namespace geomesh {

std::vector<std::uint8_t> maxWeightMatching(std::uint32_t nodeCount,
                                            const std::vector<std::uint32_t>& ends,
                                            const std::vector<std::int64_t>& weights) {
  using Graph = lemon::SmartGraph;
  Graph graph;
  graph.reserveNode(static_cast<int>(nodeCount));
  graph.reserveEdge(static_cast<int>(weights.size()));
  std::vector<Graph::Node> nodes;
  nodes.reserve(nodeCount);
  for (std::uint32_t k = 0; k < nodeCount; ++k) nodes.push_back(graph.addNode());
  Graph::EdgeMap<long long> weight(graph);
  std::vector<Graph::Edge> edges;
  edges.reserve(weights.size());
  for (std::size_t e = 0; e < weights.size(); ++e) {
    edges.push_back(graph.addEdge(nodes[ends[2 * e]], nodes[ends[2 * e + 1]]));
    weight[edges.back()] = weights[e];
  }
  lemon::MaxWeightedMatching<Graph, Graph::EdgeMap<long long>> matching(graph, weight);
  matching.run();
  std::vector<std::uint8_t> matched(weights.size(), 0);
  for (std::size_t e = 0; e < edges.size(); ++e) matched[e] = matching.matching(edges[e]) ? 1 : 0;
  return matched;
}

}  // namespace geomesh
