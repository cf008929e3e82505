// editDistance and closestNames: "did you mean" suggestions for misspelled names.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace geomesh {

// Edit distance (insertions, deletions, substitutions, and swaps of two adjacent letters, each
// counting one), ignoring case differences.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidates closest to `word` (at most `limit`), only those close enough to be a
// plausible misspelling; best first.
std::vector<std::string> closestNames(std::string_view word,
                                      std::span<const std::string> candidates,
                                      std::size_t limit = 3);

}  // namespace geomesh
