// VTK's XML UnstructuredGrid (.vtu): the cells of the legacy writer (io/vtk_cells.h) with the
// entity tag of each cell as the CellEntityIds cell data. ASCII data arrays, or (Mesh.Binary)
// inline binary ones: base64 of a UInt64 byte count followed by the little-endian values,
// which is what VTK's XML readers take for uncompressed "binary" arrays.
#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

#include "io/base64.h"
#include "io/binary_output.h"
#include "io/formats.h"
#include "io/vtk_cells.h"

namespace geomesh {

namespace {

// The values of one DataArray, as text or as little-endian bytes.
class ArrayData {
 public:
  explicit ArrayData(bool binary) : binary_(binary) {}

  template <class T>
  void add(T v) {
    if (binary_) {
      appendRaw(bytes_, v, std::endian::little);
      return;
    }
    char digits[32];
    const char* end = std::to_chars(digits, digits + sizeof digits, v).ptr;
    if (!text_.empty() && text_.back() != '\n') text_ += ' ';
    text_.append(digits, static_cast<std::size_t>(end - digits));
  }
  void endLine() {
    if (!binary_) text_ += '\n';
  }
  std::string content() const {
    if (!binary_) return text_;
    std::string sized;
    appendRaw(sized, static_cast<std::uint64_t>(bytes_.size()), std::endian::little);
    return encodeBase64(sized + bytes_) + '\n';
  }

 private:
  bool binary_;
  std::string text_;
  std::string bytes_;
};

void writeArray(std::ostream& out, const std::string& attributes, const ArrayData& data,
                bool binary) {
  out << "<DataArray " << attributes << " format=\"" << (binary ? "binary" : "ascii")
      << "\">\n"
      << data.content() << "</DataArray>\n";
}

void writePoints(std::ostream& out, const Mesh& mesh, const VtkGrid& grid, bool binary) {
  ArrayData data(binary);
  for (NodeIndex n : grid.points) {
    const Vec3 p = mesh.node(n);
    data.add(p.x);
    data.add(p.y);
    data.add(p.z);
    data.endLine();
  }
  out << "<Points>\n";
  writeArray(out, "type=\"Float64\" NumberOfComponents=\"3\"", data, binary);
  out << "</Points>\n";
}

void writeCells(std::ostream& out, const VtkGrid& grid, bool binary) {
  ArrayData connectivity(binary), offsets(binary), types(binary);
  std::int64_t start = 0;
  for (std::size_t i = 0; i < grid.offsets.size(); ++i) {
    for (std::int64_t k = start; k < grid.offsets[i]; ++k) connectivity.add(grid.connectivity[k]);
    connectivity.endLine();
    start = grid.offsets[i];
    offsets.add(start);
    offsets.endLine();
    types.add(grid.types[i]);
    types.endLine();
  }
  out << "<Cells>\n";
  writeArray(out, "type=\"Int64\" Name=\"connectivity\"", connectivity, binary);
  writeArray(out, "type=\"Int64\" Name=\"offsets\"", offsets, binary);
  writeArray(out, "type=\"UInt8\" Name=\"types\"", types, binary);
  out << "</Cells>\n";
}

void writeEntityTags(std::ostream& out, const VtkGrid& grid, bool binary) {
  ArrayData tags(binary);
  for (std::int32_t tag : grid.entityTags) {
    tags.add(tag);
    tags.endLine();
  }
  out << "<CellData Scalars=\"CellEntityIds\">\n";
  writeArray(out, "type=\"Int32\" Name=\"CellEntityIds\"", tags, binary);
  out << "</CellData>\n";
}

}  // namespace

// Named by the vtu row of io/formats.cpp; saves what the legacy VTK writer saves.
void writeVtu(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const VtkGrid grid = buildVtkGrid(model, mesh, options.saveAll);
  const bool binary = options.binary;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
      << "<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << grid.points.size() << "\" NumberOfCells=\""
      << grid.types.size() << "\">\n";
  writePoints(out, mesh, grid, binary);
  writeCells(out, grid, binary);
  writeEntityTags(out, grid, binary);
  out << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace geomesh
