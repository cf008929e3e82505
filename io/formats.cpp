// The table of mesh file formats and the lookups over it.
#include "io/formats.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/msh_reader.h"
#include "io/msh_writer.h"

namespace geomesh {

// Defined in the file of each format.
void writeVtk(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void readVtk(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
void writeVtu(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void writeStl(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void readStl(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
void writePly(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void readPly(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
void writeOff(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void readOff(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
void writeObj(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void readObj(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
void writeUnv(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void readUnv(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
void writeMedit(std::ostream& out, const Model& model, const Mesh& mesh,
                const MeshWriteOptions& options);
void readMedit(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
void writeBdf(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void readBdf(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
void writeInp(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void writeSu2(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void writeCgns(const std::string& path, const Model& model, const Mesh& mesh,
               const MeshWriteOptions& options);
void readCgns(const std::string& path, Model& model, Mesh& mesh);
void writeHtml(std::ostream& out, const Model& model, const Mesh& mesh,
               const MeshWriteOptions& options);
void writeSvg(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);
void writePng(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options);

namespace {

void writeMsh41(std::ostream& out, const Model& model, const Mesh& mesh,
                const MeshWriteOptions& options) {
  writeMsh(out, model, mesh,
           {options.saveAll, options.binary, 4.1, options.partitionOldStyleMsh2,
            options.onlyPartition});
}

void writeMsh22(std::ostream& out, const Model& model, const Mesh& mesh,
                const MeshWriteOptions& options) {
  writeMsh(out, model, mesh,
           {options.saveAll, options.binary, 2.2, options.partitionOldStyleMsh2,
            options.onlyPartition});
}

// One row per format. Adding a format: its file in io/ defines the writer (and reader), and
// one row here names them.
constexpr MeshFormat kFormats[] = {
    {"msh41 msh4 msh", ".msh", 1, 4.0, writeMsh41, readMsh, 4, nullptr, nullptr, true},
    {"msh22 msh2", ".msh", 1, 0.0, writeMsh22, readMsh, 4, nullptr, nullptr, true},
    {"vtk", ".vtk", 16, 0.0, writeVtk, readVtk, 2},
    {"vtu", ".vtu", 0, 0.0, writeVtu, nullptr, 2},
    {"stl", ".stl", 27, 0.0, writeStl, readStl, 1},
    {"ply", ".ply", 0, 0.0, writePly, readPly, 1},
    {"off", ".off", 0, 0.0, writeOff, readOff, 1},
    {"obj", ".obj", 0, 0.0, writeObj, readObj, 1},
    {"unv", ".unv", 2, 0.0, writeUnv, readUnv, 2},
    {"mesh", ".mesh", 30, 0.0, writeMedit, readMedit, 2},
    {"bdf", ".bdf .nas", 31, 0.0, writeBdf, readBdf, 2},
    {"cgns", ".cgns", 32, 0.0, nullptr, nullptr, 2, writeCgns, readCgns},
    {"inp", ".inp", 39, 0.0, writeInp, nullptr, 2},
    {"su2", ".su2", 42, 0.0, writeSu2, nullptr, 1},
    {"svg", ".svg", 0, 0.0, writeSvg, nullptr, 4, nullptr, nullptr, false, true},
    {"png", ".png", 0, 0.0, writePng, nullptr, 4, nullptr, nullptr, false, true},
    {"html", ".html .htm", 0, 0.0, writeHtml, nullptr, 4},
};

// The words of a space-separated list.
std::vector<std::string_view> words(std::string_view list) {
  std::vector<std::string_view> result;
  while (!list.empty()) {
    const std::size_t end = list.find(' ');
    result.push_back(list.substr(0, end));
    list = end == std::string_view::npos ? std::string_view() : list.substr(end + 1);
  }
  return result;
}

bool contains(std::string_view list, std::string_view word) {
  for (std::string_view w : words(list))
    if (w == word) return true;
  return false;
}

// The first row that matches and whose minVersion admits `version`, else the last row that
// matches (the oldest version).
template <class Matches>
const MeshFormat* findVersion(double version, Matches matches) {
  const MeshFormat* last = nullptr;
  for (const MeshFormat& format : kFormats) {
    if (!matches(format)) continue;
    if (version >= format.minVersion) return &format;
    last = &format;
  }
  return last;
}

// Items joined by ", ", each once.
std::string joinedOnce(const std::vector<std::string>& items) {
  std::string text;
  std::vector<std::string> seen;
  for (const std::string& item : items) {
    if (std::find(seen.begin(), seen.end(), item) != seen.end()) continue;
    seen.push_back(item);
    text += (text.empty() ? "" : ", ") + item;
  }
  return text;
}

// The words of one field of the rows that can `use` (write or read), each once.
template <class Use>
std::string listed(std::string_view MeshFormat::*field, Use use) {
  std::vector<std::string> items;
  for (const MeshFormat& format : kFormats)
    if (std::invoke(use, format))
      for (std::string_view word : words(format.*field)) items.emplace_back(word);
  return joinedOnce(items);
}

}  // namespace

bool savesGroupsOfDimension(int saveGroups, int dim) {
  if (saveGroups >= 0) return saveGroups != 0;
  int digits = -saveGroups;
  for (int k = 0; k < dim; ++k) digits /= 10;
  return digits % 10 == 1;
}

bool MeshFormat::isNamed(std::string_view name) const { return contains(names, name); }

bool MeshFormat::hasExtension(std::string_view extension) const {
  return contains(extensions, extension);
}

std::span<const MeshFormat> meshFormats() { return kFormats; }

std::string orderUnsupportedReason(const MeshFormat& format, int order) {
  if (order <= format.maxOrder) return "";
  return std::string(format.name()) + " files hold elements up to order " +
         std::to_string(format.maxOrder);
}

const MeshFormat* findFormatByName(std::string_view name) {
  for (const MeshFormat& format : kFormats)
    if (format.writes() && format.isNamed(name)) return &format;
  return nullptr;
}

const MeshFormat* findFormatByExtension(std::string_view extension, double version) {
  return findVersion(version, [&](const MeshFormat& f) {
    return f.writes() && f.hasExtension(extension);
  });
}

const MeshFormat* findFormatByCode(int code, double version) {
  if (code == 0) return nullptr;  // formats without a code are chosen by name or extension
  return findVersion(version, [&](const MeshFormat& f) { return f.writes() && f.code == code; });
}

const MeshFormat* findReaderByExtension(std::string_view extension) {
  for (const MeshFormat& format : kFormats)
    if (format.reads() && format.hasExtension(extension)) return &format;
  return nullptr;
}

std::string formatNameList() { return listed(&MeshFormat::names, &MeshFormat::writes); }

std::string formatNameGroups() {
  std::vector<std::string> groups;
  for (const MeshFormat& format : kFormats) {
    if (!format.writes()) continue;
    const std::vector<std::string_view> names = words(format.names);
    std::string group(names.front());
    for (std::size_t i = 1; i < names.size(); ++i)
      group += (i == 1 ? " (" : ", ") + std::string(names[i]);
    groups.push_back(names.size() > 1 ? group + ")" : group);
  }
  return joinedOnce(groups);
}

std::string writtenExtensionList() {
  return listed(&MeshFormat::extensions, &MeshFormat::writes);
}

std::string readExtensionList() { return listed(&MeshFormat::extensions, &MeshFormat::reads); }

std::string formatCodeList() {
  std::vector<std::string> codes;
  for (const MeshFormat& format : kFormats)
    if (format.writes() && format.code != 0)
      codes.push_back(std::to_string(format.code) + " (" +
                      std::string(words(format.extensions).front().substr(1)) + ")");
  return joinedOnce(codes);
}

void writeMeshFile(const std::string& path, const MeshFormat& format, const Model& model,
                   const Mesh& mesh, const MeshWriteOptions& options) {
  if (!format.writes())
    throw std::runtime_error("cannot write '" + path + "': " + std::string(format.name()) +
                             " files are only read");
  if (format.writeFile)
    return writeFileAtomicallyByPath(path, [&](const std::string& temporary) {
      format.writeFile(temporary, model, mesh, options);
    });
  if (format.holdsPartitions && options.splitPartitions && mesh.partitions()) {
    const std::filesystem::path whole(path);
    for (int p = 1; p <= mesh.partitions()->count; ++p) {
      std::filesystem::path part = whole;
      part.replace_filename(whole.stem().string() + "_" + std::to_string(p) +
                            whole.extension().string());
      MeshWriteOptions one = options;
      one.onlyPartition = p;
      writeFileAtomically(part.string(),
                          [&](std::ostream& out) { format.write(out, model, mesh, one); });
    }
    return;
  }
  writeFileAtomically(path, [&](std::ostream& out) { format.write(out, model, mesh, options); });
}

void readMeshFile(const std::string& path, const MeshFormat& format, Model& model, Mesh& mesh) {
  if (!format.reads())
    throw std::runtime_error("cannot read '" + path + "': " + std::string(format.name()) +
                             " files are only written");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot open '" + path + "'");
  if (format.readFile) {
    file.close();
    return format.readFile(path, model, mesh);
  }
  format.read(file, model, mesh, path);
}

}  // namespace geomesh
