// scratch::path: per-process temporary paths for the files tests write.
#pragma once
// Where tests that write files write them: a path in the temporary directory that is unique
// to the running process, so that test runs of several build trees at once never touch each
// other's files.
#include <filesystem>
#include <string>

#include <unistd.h>

namespace geomesh::scratch {

inline std::filesystem::path path(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("geomesh-" + std::to_string(::getpid()) + "-" + name);
}

}  // namespace geomesh::scratch
