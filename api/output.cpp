// Output files of a session: mesh (through the format table), unrolled geometry, options.
#include "api/output.h"

#include <filesystem>
#include <ostream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "kernel/unrolled_geo_hooks.h"
#include "stdlib/clamped_integer.h"

namespace geomesh::api {

namespace {

constexpr int kFormatByExtension = 10;  // Mesh.Format's "auto"

const MeshFormat& formatNamed(const std::string& name) {
  if (const MeshFormat* format = findFormatByName(name)) return *format;
  throw std::invalid_argument("unsupported output format '" + name +
                              "' (supported: " + formatNameList() + ")");
}

const MeshFormat& formatOfExtension(const std::string& path, double version) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (const MeshFormat* format = findFormatByExtension(extension, version)) return *format;
  throw std::invalid_argument("cannot write '" + path + "': the '" + extension +
                              "' format is not supported yet (only " + writtenExtensionList() +
                              ")");
}

}  // namespace

const MeshFormat& outputFormat(const OptionRegistry& options, const std::string& path,
                               const std::string& formatName) {
  if (!formatName.empty()) return formatNamed(formatName);
  const double version = options.number("Mesh.MshFileVersion");
  const int code = clampedInteger<int>(options.number("Mesh.Format"));
  if (code == kFormatByExtension) return formatOfExtension(path, version);
  if (const MeshFormat* format = findFormatByCode(code, version)) return *format;
  throw std::invalid_argument("Mesh.Format " + std::to_string(code) +
                              " is not supported yet (supported: " + formatCodeList() + ", " +
                              std::to_string(kFormatByExtension) + " (by extension))");
}

MeshWriteOptions writeOptions(const OptionRegistry& options) {
  MeshWriteOptions w;
  w.saveAll = options.number("Mesh.SaveAll") != 0;
  w.binary = options.number("Mesh.Binary") != 0;
  return w;
}

void writeMesh(const Session& session, const std::string& path, const MeshFormat& format) {
  writeMeshFile(path, format, session.model(), session.mesh(), writeOptions(session.options()));
}

void writeUnrolledGeometry(Session& session, const std::string& path) {
  writeFileAtomically(path, [&](std::ostream& out) {
    session.factories().writeUnrolled(
        out, meshConstraintHooks(session.model().meshConstraints()), path + ".xao");
  });
}

void writeChangedOptions(const Session& session, const std::string& path) {
  writeFileAtomically(path, [&](std::ostream& out) {
    for (const auto& option : session.options().all())
      if (option.number != option.defaultNumber || option.text != option.defaultText)
        out << optionListingLine(option) << '\n';
  });
}

}  // namespace geomesh::api
