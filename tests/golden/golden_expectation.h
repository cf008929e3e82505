// Expectation and GoldenCase: the figures, output and exit status a golden script must meet.
#pragma once

#include <string>
#include <vector>

namespace geomesh::golden {

// One expected figure of a golden script's summary. In a `.expected` file, one per line:
//   nodes: 120..160          a range (inclusive)
//   area: 2 +- 1e-9          a value with an absolute tolerance
//   area: 2 +- 1%            ... or a relative one
//   quality.min: >= 0.3      a bound
//   elements.line: 40        an exact value
//   physical: 2 1 plate      a physical group (dim, tag, name) that must be in the file
//   stdout: text             a line the script must print (in order)
//   args: -2 -clscale 0.5    the command line (without the script and -o)
//   exit: 1                  the expected exit status (default 0)
//   stderr: text             a fragment the diagnostics must contain
// Blank lines and lines starting with '#' are ignored.
struct Expectation {
  std::string key;
  enum class Kind { Range, Tolerance, AtLeast, AtMost, Exact, Text } kind = Kind::Exact;
  double low = 0, high = 0;
  std::string text;
  int line = 0;
};

struct GoldenCase {
  std::vector<std::string> args;
  int exitStatus = 0;
  std::vector<Expectation> figures;
  std::vector<std::string> physicals;  // "dim tag name"
  std::vector<std::string> stdoutLines;
  std::vector<std::string> stderrFragments;
};

// Reads a .expected file; throws std::runtime_error naming the line of a malformed entry.
GoldenCase readExpectations(const std::string& path);

// Whether `value` satisfies the expectation; if not, `why` says how it differs.
bool satisfies(const Expectation& e, double value, std::string& why);

}  // namespace geomesh::golden
