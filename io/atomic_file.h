// Writing a file so that it appears complete or not at all.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace geomesh {

// Runs `write` on `path` + ".partial", then renames that file to `path`. Any failure (an
// exception from `write`, a stream error, a failed rename) removes the partial file and throws
// std::runtime_error "cannot write '<path>': <reason>" (std::bad_alloc passes through as is).
// Nothing but a complete file is ever left at `path`. Every file geomesh writes goes through
// here.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// The same for writers that open the file themselves (libraries that take a path): `write`
// creates a complete file at the temporary path it is given.
void writeFileAtomicallyByPath(const std::string& path,
                               const std::function<void(const std::string&)>& write);

}  // namespace geomesh
