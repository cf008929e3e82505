// Writing views: the parsed .pos format, and writeView choosing the format by extension.
#include <filesystem>
#include <system_error>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/real_text.h"
#include "io/view_file_parts.h"
#include "io/view_files.h"

namespace geomesh {

namespace {

// A string between double quotes as the script lexers read it back: characters as they are,
// except a quote, written \" (a backslash is no escape otherwise, as in the reference).
void writeQuoted(std::ostream& out, const std::string& s) {
  out << '"';
  for (char c : s) {
    if (c == '"') out << '\\';
    out << c;
  }
  out << '"';
}

// Reals separated by commas, each in the fewest digits that read back exactly.
void writeReals(std::ostream& out, const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) out << ',';
    writeShortestReal(out, v[i]);
  }
}

void writeList(std::ostream& out, const post::ElementList& list) {
  std::string letters{post::kindLetter(list.kind), post::shapeLetter(list.shape)};
  if (list.order == 2) letters += '2';
  const std::size_t xyz = 3 * std::size_t(list.nodesPerElement);
  const std::size_t values = list.valuesPerElement();
  for (std::size_t e = 0; e < list.size(); ++e) {
    out << letters << '(';
    writeReals(out, list.coordinates.data() + e * xyz, xyz);
    out << "){";
    writeReals(out, list.values.data() + e * values, values);
    out << "};\n";
  }
}

void writeText(std::ostream& out, const post::TextItem& t) {
  out << (t.dimension == 3 ? "T3(" : "T2(");
  const double place[4] = {t.x, t.y, t.dimension == 3 ? t.z : t.style, t.style};
  writeReals(out, place, t.dimension == 3 ? 4 : 3);
  out << "){";
  for (std::size_t i = 0; i < t.text.size(); ++i) {
    if (i > 0) out << ',';
    writeQuoted(out, t.text[i]);
  }
  out << "};\n";
}

std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

void writeParsedPos(std::ostream& out, const post::View& view) {
  out << "View ";
  writeQuoted(out, view.name);
  out << " {\n";
  if (!view.times.empty()) {
    out << "TIME{";
    writeReals(out, view.times.data(), view.times.size());
    out << "};\n";
  }
  for (const post::ElementList& list : view.lists) writeList(out, list);
  for (const post::TextItem& t : view.texts) writeText(out, t);
  out << "};\n";
}

void writeView(const post::View& view, const std::string& path, const Mesh& mesh, double mshVersion,
               bool append) {
  const std::string ext = extensionOf(path);
  std::string before;
  std::error_code unreadable;
  if (append && std::filesystem::exists(path, unreadable)) before = readViewFile(path);
  if (ext == ".pos") {
    writeFileAtomically(path, [&](std::ostream& out) {
      out << before;
      writeParsedPos(out, view);
    });
  } else if (ext == ".msh") {
    if (mshVersion != 4.1 && mshVersion != 2.2)
      throw std::runtime_error("cannot write '" + path + "': unsupported MSH version " +
                               std::to_string(mshVersion) + " (4.1 and 2.2 are supported)");
    // Appended data sections follow the mesh already in the file (written with an earlier view
    // of the same mesh); a list-based view brings its own mesh and replaces the file.
    const bool dataOnly = !before.empty() && view.meshData.has_value();
    writeFileAtomically(path, [&](std::ostream& out) {
      if (dataOnly) out << before;
      writeMshView(out, view, mesh, mshVersion, dataOnly);
    });
  } else {
    throw std::runtime_error("cannot write view '" + view.name + "' to '" + path +
                             "': unknown view format '" + ext + "' (.pos and .msh are supported)");
  }
}

}  // namespace geomesh
