// VtkArrayReader: the typed values of a legacy VTK file (ASCII or big-endian binary) and its
// attribute sections (CELL_DATA, POINT_DATA, FIELD), for the legacy VTK reader.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_scanner.h"

namespace geomesh {

// A one-component array of cell data: its name, whether its declared type is an integer type,
// and its values.
struct VtkCellArray {
  std::string name;
  bool integral = false;
  std::vector<double> values;
  int line = 0;  // where its values start, for errors
};

class VtkArrayReader {
 public:
  VtkArrayReader(MeshScanner& in, bool binary) : in_(in), binary_(binary) {}

  // Whether the next line starts with `word`; binary data that follows is left untouched.
  bool nextIs(std::string_view word);

  MeshScanner& scanner() { return in_; }
  bool binary() const { return binary_; }

  // A count word, checked against what the rest of the file could hold at `bytesEach`.
  std::uint64_t count(std::string_view what, std::size_t bytesEach = 1);
  // `count` values stored as `type` ("float", "int", "vtktypeint64", ...), appended to `out`;
  // integer arrays refuse fractional ASCII values.
  void read(std::string_view type, std::uint64_t count, std::vector<double>& out);
  void read(std::string_view type, std::uint64_t count, std::vector<std::int64_t>& out);
  void skip(std::string_view type, std::uint64_t count);
  static bool isIntegral(std::string_view type);

  // The arrays after "CELL_DATA n" or "POINT_DATA n" (read), up to the next section keyword;
  // the one-component arrays go to `kept` when it is not null.
  void readAttributes(std::uint64_t n, std::vector<VtkCellArray>* kept);
  // The arrays of "FIELD name k" (read), of `n` tuples when n > 0.
  void readField(std::vector<VtkCellArray>* kept, std::uint64_t n);
  // A METADATA block (VTK 5), whose keyword has been read: lines up to an empty one.
  void skipMetadata();

 private:
  NumberType typeNamed(std::string_view name);
  template <class Out>
  void readValues(std::string_view type, std::uint64_t count, std::vector<Out>& out);
  void readOrSkip(std::string name, std::string_view type, std::uint64_t count,
                  std::uint64_t components, std::vector<VtkCellArray>* kept);
  void readScalars(std::uint64_t n, std::vector<VtkCellArray>* kept);
  void skipAttribute(const std::string& keyword, std::uint64_t n);
  void skipLookupTableLine();

  MeshScanner& in_;
  bool binary_;
};

}  // namespace geomesh
