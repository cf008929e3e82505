// Output files of a session: mesh (through the format table), unrolled geometry, options.
#include "api/output.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <ostream>
#include <set>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/msh_content.h"
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
  w.saveGroupsOfElements = clampedInteger<int>(options.number("Mesh.SaveGroupsOfElements"));
  w.saveGroupsOfNodes = clampedInteger<int>(options.number("Mesh.SaveGroupsOfNodes"));
  w.partitionOldStyleMsh2 = options.number("Mesh.PartitionOldStyleMsh2") != 0;
  w.splitPartitions = options.number("Mesh.PartitionSplitMeshFiles") != 0;
  const auto pixels = [&](const char* print, const char* graphics) {
    const double size = options.number(print);
    return clampedInteger<int>(size > 0 ? size : options.number(graphics));
  };
  w.pictureWidth = pixels("Print.Width", "General.GraphicsWidth");
  w.pictureHeight = pixels("Print.Height", "General.GraphicsHeight");
  const std::array<double, 3> rotation{options.number("General.RotationX"),
                                       options.number("General.RotationY"),
                                       options.number("General.RotationZ")};
  if (rotation != std::array<double, 3>{0, 0, 0}) w.viewRotation = rotation;
  return w;
}

std::string unsavedEntities(const Model& model, const Mesh& mesh) {
  static constexpr const char* kKinds[] = {"point", "curve", "surface", "volume"};
  const std::set<EntityId> grouped = presentPhysicalEntities(model, mesh);
  std::set<int> groupedDims;
  for (EntityId id : grouped) groupedDims.insert(id.dim);
  std::vector<std::string> names;
  std::size_t elements = 0;
  for (const auto& [id, em] : mesh.entities()) {
    const std::size_t count = em.elementCount();
    if (count == 0 || !groupedDims.contains(id.dim) || grouped.contains(id)) continue;
    elements += count;
    names.push_back(std::string(id.dim >= 0 && id.dim <= 3 ? kKinds[id.dim] : "entity") + " " +
                    std::to_string(id.tag));
  }
  if (names.empty()) return "";
  constexpr std::size_t kShown = 8;
  std::string list;
  for (std::size_t i = 0; i < std::min(names.size(), kShown); ++i)
    list += (i == 0 ? "" : ", ") + names[i];
  if (names.size() > kShown) list += " and " + std::to_string(names.size() - kShown) + " more";
  return list + " (" + std::to_string(elements) + " element" + (elements == 1 ? "" : "s") + ")";
}

void writeMesh(const Session& session, const std::string& path, const MeshFormat& format) {
  const MeshWriteOptions options = writeOptions(session.options());
  if (!options.saveAll && !format.showsAllElements)
    if (const std::string left = unsavedEntities(session.model(), session.mesh()); !left.empty())
      session.log().warning(
          "'" + path + "' leaves out the elements of " + left +
          ": they are in no physical group while others of their dimension are; -save_all "
          "(Mesh.SaveAll = 1) saves them too");
  writeMeshFile(path, format, session.model(), session.mesh(), options);
}

void writeUnrolledGeometry(Session& session, const std::string& path) {
  writeFileAtomically(path, [&](std::ostream& out) {
    session.factories().writeUnrolled(out, meshConstraintHooks(session.model().meshConstraints()),
                                      path + ".xao");
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
