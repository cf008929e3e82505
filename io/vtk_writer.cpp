// Legacy VTK: DATASET UNSTRUCTURED_GRID with POINTS, CELLS, CELL_TYPES and the entity tag of
// each cell as CELL_DATA, in ASCII or (Mesh.Binary) in VTK's big-endian binary form. Linear
// elements and VTK's quadratic cells (io/vtk_cells.h).
#include <bit>
#include <charconv>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>

#include "io/binary_output.h"
#include "io/formats.h"
#include "io/vtk_cells.h"

namespace geomesh {

namespace {

void writeReal(std::ostream& out, double v) {
  char digits[32];
  out.write(digits, std::to_chars(digits, digits + sizeof digits, v, std::chars_format::general,
                                  16).ptr - digits);
}

// Binary legacy files hold their numbers big-endian, whatever the machine.
class BigEndianBlock {
 public:
  template <class T>
  void add(T v) {
    appendRaw(bytes_, v, std::endian::big);
  }
  void writeTo(std::ostream& out) {
    bytes_ += '\n';
    out.write(bytes_.data(), static_cast<std::streamsize>(bytes_.size()));
    bytes_.clear();
  }

 private:
  std::string bytes_;
};

std::size_t cellListSize(const VtkGrid& grid) {
  return grid.connectivity.size() + grid.types.size();
}

void writePoints(std::ostream& out, const Mesh& mesh, const VtkGrid& grid, bool binary) {
  out << "POINTS " << grid.points.size() << " double\n";
  BigEndianBlock block;
  for (NodeIndex n : grid.points) {
    const Vec3 p = mesh.node(n);
    if (binary) {
      block.add(p.x);
      block.add(p.y);
      block.add(p.z);
      continue;
    }
    writeReal(out, p.x);
    out << ' ';
    writeReal(out, p.y);
    out << ' ';
    writeReal(out, p.z);
    out << '\n';
  }
  if (binary) block.writeTo(out);
}

void writeCells(std::ostream& out, const VtkGrid& grid, bool binary) {
  out << "CELLS " << grid.types.size() << ' ' << cellListSize(grid) << '\n';
  BigEndianBlock block;
  std::int64_t start = 0;
  for (std::int64_t end : grid.offsets) {
    if (binary) {
      block.add(static_cast<std::int32_t>(end - start));
      for (std::int64_t k = start; k < end; ++k)
        block.add(static_cast<std::int32_t>(grid.connectivity[k]));
    } else {
      out << end - start;
      for (std::int64_t k = start; k < end; ++k) out << ' ' << grid.connectivity[k];
      out << '\n';
    }
    start = end;
  }
  if (binary) block.writeTo(out);
}

// One integer per cell, after `header`.
template <class Values>
void writeCellIntegers(std::ostream& out, const std::string& header, const Values& values,
                       bool binary) {
  out << header;
  BigEndianBlock block;
  for (auto v : values) {
    if (binary)
      block.add(static_cast<std::int32_t>(v));
    else
      out << static_cast<std::int32_t>(v) << '\n';
  }
  if (binary) block.writeTo(out);
}

// The classic CELLS list holds 32-bit integers.
void checkBinarySizes(const VtkGrid& grid) {
  if (cellListSize(grid) > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("the mesh is too large for a legacy VTK file: its cell list has " +
                                std::to_string(cellListSize(grid)) + " numbers");
}

}  // namespace

// Named by the vtk row of io/formats.cpp. Saves what an MSH file would (the elements of
// physical groups only, when there are groups and Mesh.SaveAll is off).
void writeVtk(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const VtkGrid grid = buildVtkGrid(model, mesh, options.saveAll);
  const bool binary = options.binary;
  if (binary) checkBinarySizes(grid);
  out << "# vtk DataFile Version 2.0\ngeomesh mesh\n"
      << (binary ? "BINARY" : "ASCII") << "\nDATASET UNSTRUCTURED_GRID\n";
  writePoints(out, mesh, grid, binary);
  writeCells(out, grid, binary);
  writeCellIntegers(out, "CELL_TYPES " + std::to_string(grid.types.size()) + "\n", grid.types,
                    binary);
  writeCellIntegers(out,
                    "CELL_DATA " + std::to_string(grid.types.size()) +
                        "\nSCALARS CellEntityIds int 1\nLOOKUP_TABLE default\n",
                    grid.entityTags, binary);
}

}  // namespace geomesh
