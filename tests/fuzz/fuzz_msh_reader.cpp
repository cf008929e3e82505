// Feeds arbitrary bytes to the MSH reader: it must either read a mesh or throw MshReadError.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "io/msh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  geomesh::Model model;
  geomesh::Mesh mesh;
  try {
    geomesh::readMsh(in, model, mesh, "fuzz.msh");
  } catch (const geomesh::MshReadError&) {
  }
  return 0;
}
