// What a CGNS file holds, as far as geomesh writes CGNS, read back through libcgns: for checking
// written files without the library's header outside io/cgns_writer.cpp.
#pragma once

#include <string>
#include <vector>

namespace geomesh {

struct CgnsSectionSummary {
  std::string name;
  std::string type;  // CGNS's name for it: "TETRA_10"
  long long first = 0, last = 0;
  std::vector<long long> connectivity;
};

struct CgnsBoundarySummary {
  std::string name;
  std::string family;
  std::string location;  // "FaceCenter"...
  std::vector<long long> elements;
};

// The first base and its first zone.
struct CgnsSummary {
  std::string base, zone;
  int cellDim = 0, physicalDim = 0;
  bool unstructured = false;
  long long vertices = 0, cells = 0;
  std::vector<double> x, y, z;
  std::vector<CgnsSectionSummary> sections;
  std::vector<CgnsBoundarySummary> boundaries;
  std::vector<std::string> families;
};

// Throws std::runtime_error naming the file when it cannot be read.
CgnsSummary summarizeCgnsFile(const std::string& path);

}  // namespace geomesh
