// Writing through a sibling temporary file renamed into place.
#include "io/atomic_file.h"

#include <filesystem>
#include <system_error>
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

// Runs `write` on the sibling temporary path, then renames it to `path`; see the header.
void replaceAtomically(const std::string& path,
                       const std::function<void(const std::filesystem::path&)>& write) {
  // A sibling of the destination, so that the final rename stays on one file system.
  std::filesystem::path partial = path;
  partial += ".partial";
  std::error_code ignored;
  try {
    write(partial);
    std::filesystem::rename(partial, path);
  } catch (const std::bad_alloc&) {
    std::filesystem::remove(partial, ignored);
    throw;
  } catch (const std::exception& e) {
    std::filesystem::remove(partial, ignored);
    throw std::runtime_error("cannot write '" + path + "': " + e.what());
  }
}

}  // namespace

void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& write) {
  replaceAtomically(path, [&](const std::filesystem::path& partial) {
    writeTemporary(partial, write);
  });
}

void writeFileAtomicallyByPath(const std::string& path,
                               const std::function<void(const std::string&)>& write) {
  replaceAtomically(path, [&](const std::filesystem::path& partial) {
    write(partial.string());
    std::error_code unreadable;
    if (!std::filesystem::exists(partial, unreadable))
      throw std::runtime_error("no file was written at '" + partial.string() + "'");
  });
}

}  // namespace geomesh
