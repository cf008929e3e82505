// readMsh and MshReadError: MSH 4.1 and 2.2 files, ASCII or binary, into a model and a mesh.
#pragma once

#include <iosfwd>
#include <stdexcept>
#include <string>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// A malformed or unsupported MSH file. The message starts with "name:line: " (for binary data,
// the line where the data block starts).
class MshReadError : public std::runtime_error {
 public:
  MshReadError(const std::string& message, int line)
      : std::runtime_error(message), line(line) {}
  int line;
};

// Reads an MSH 4.1 (ASCII or binary) or 2.2 (ASCII or binary) file into `model` and `mesh`,
// replacing their content. The model gets the file's entities, with their bounding entities
// (4.1 only) and physical groups but no geometry; the mesh gets nodes classified on those
// entities and their elements. Any malformed input throws MshReadError, never crashes.
// `name` prefixes error messages.
void readMsh(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
void readMshFile(const std::string& path, Model& model, Mesh& mesh);

}  // namespace geomesh
