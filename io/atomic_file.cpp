// Writing through a sibling temporary file renamed into place.
#include "io/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>

namespace geomesh {

namespace {

// Writes and closes the temporary file; throws a message naming what failed.
void writeTemporary(const std::filesystem::path& partial,
                    const std::function<void(std::ostream&)>& write) {
  std::ofstream out(partial, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot open '" + partial.string() + "' for writing");
  write(out);
  out.close();
  if (!out) throw std::runtime_error("error while writing '" + partial.string() + "'");
}

}  // namespace

void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& write) {
  // A sibling of the destination, so that the final rename stays on one file system.
  std::filesystem::path partial = path;
  partial += ".partial";
  std::error_code ignored;
  try {
    writeTemporary(partial, write);
    std::filesystem::rename(partial, path);
  } catch (const std::bad_alloc&) {
    std::filesystem::remove(partial, ignored);
    throw;
  } catch (const std::exception& e) {
    std::filesystem::remove(partial, ignored);
    throw std::runtime_error("cannot write '" + path + "': " + e.what());
  }
}

}  // namespace geomesh
