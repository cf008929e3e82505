// Reading an MSH file given as text, for the reader's tests: the model and mesh it gives, or
// the error it stops with.
#pragma once

#include <sstream>
#include <string>

#include "io/msh_reader.h"

namespace geomesh::testing {

struct ReadResult {
  Model model;
  Mesh mesh;
};

inline ReadResult read(const std::string& text, const std::string& name = "test.msh") {
  ReadResult r;
  std::istringstream in(text);
  readMsh(in, r.model, r.mesh, name);
  return r;
}

// The reader's error message, or "no error".
inline std::string readError(const std::string& text, const std::string& name = "test.msh") {
  try {
    read(text, name);
  } catch (const MshReadError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace geomesh::testing
