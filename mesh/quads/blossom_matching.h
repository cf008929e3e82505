// maximumMatching: Edmonds' blossom algorithm (LEMON) behind a plain C++17 interface.
#pragma once

// Plain C++17 interface: blossom_matching.cpp is compiled as C++17 (LEMON's headers are not
// C++20).
#include <cstdint>
#include <vector>

namespace geomesh {

// A maximum-cardinality matching (Edmonds' blossom algorithm, by LEMON) of the graph on
// `nodeCount` nodes whose edge e joins ends[2e] and ends[2e + 1], grown from the matching
// `initial` (one flag per edge; it must be a matching) by augmenting paths, so that most of
// its pairs stay. Returns one flag per edge: 1 when the edge is matched.
std::vector<std::uint8_t> maximumMatching(std::uint32_t nodeCount,
                                          const std::vector<std::uint32_t>& ends,
                                          const std::vector<std::uint8_t>& initial);

}  // namespace geomesh
