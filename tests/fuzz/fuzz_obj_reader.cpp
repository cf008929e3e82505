// Feeds arbitrary bytes to the Wavefront OBJ reader: it must either read a mesh or throw
// MeshReadError.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "io/formats.h"
#include "io/mesh_scanner.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const geomesh::MeshFormat* const obj = geomesh::findReaderByExtension(".obj");
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  geomesh::Model model;
  geomesh::Mesh mesh;
  try {
    obj->read(in, model, mesh, "fuzz.obj");
  } catch (const geomesh::MeshReadError&) {
  }
  return 0;
}
