// PLY reader: ASCII, binary_little_endian and binary_big_endian files. The x, y, z properties
// of the "vertex" element give the nodes; the vertex_indices (or vertex_index) list of the
// "face" element gives triangles and quadrangles of one discrete surface. Other elements and
// properties are read past.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <istream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/mesh_scanner.h"
#include "io/polygon_faces.h"

namespace geomesh {

namespace {

using PlyType = NumberType;

struct PlyProperty {
  std::string name;
  PlyType type;
  bool list = false;
  PlyType countType;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding { Ascii, LittleEndian, BigEndian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
};

PlyType typeNamed(const MeshScanner& in, std::string_view name) {
  if (name == "char" || name == "int8") return {1, 'i'};
  if (name == "uchar" || name == "uint8") return {1, 'u'};
  if (name == "short" || name == "int16") return {2, 'i'};
  if (name == "ushort" || name == "uint16") return {2, 'u'};
  if (name == "int" || name == "int32") return {4, 'i'};
  if (name == "uint" || name == "uint32") return {4, 'u'};
  if (name == "float" || name == "float32") return {4, 'f'};
  if (name == "double" || name == "float64") return {8, 'f'};
  in.fail("unknown property type '" + std::string(name.substr(0, 40)) + "'");
}

void readProperty(MeshScanner& in, const std::vector<std::string_view>& w, PlyHeader& header) {
  if (header.elements.empty()) in.fail("a property before any element");
  PlyProperty p;
  if (w.size() == 5 && w[1] == "list") {
    p = {std::string(w[4]), typeNamed(in, w[3]), true, typeNamed(in, w[2])};
    if (p.countType.kind == 'f') in.fail("a list count of a floating-point type");
  } else if (w.size() == 3) {
    p = {std::string(w[2]), typeNamed(in, w[1]), false, {}};
  } else {
    in.fail("expected 'property type name' or 'property list count_type type name'");
  }
  header.elements.back().properties.push_back(std::move(p));
}

PlyHeader readHeader(MeshScanner& in) {
  if (in.line() != "ply") in.fail("not a PLY file: no 'ply' line", 1);
  PlyHeader header;
  bool format = false;
  for (;;) {
    const std::vector<std::string_view> w = wordsOf(in.line());
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (w.size() != 3 || w[2] != "1.0") in.fail("expected 'format <encoding> 1.0'");
      if (w[1] == "ascii") header.encoding = PlyEncoding::Ascii;
      else if (w[1] == "binary_little_endian") header.encoding = PlyEncoding::LittleEndian;
      else if (w[1] == "binary_big_endian") header.encoding = PlyEncoding::BigEndian;
      else in.fail("unknown PLY format '" + std::string(w[1].substr(0, 40)) + "'");
      format = true;
    } else if (w[0] == "element" && w.size() == 3) {
      header.elements.push_back({std::string(w[1]), parseNumber<std::uint64_t>(in, w[2],
                                                                             "an element count"),
                                 {}});
    } else if (w[0] == "property") {
      readProperty(in, w, header);
    } else {
      in.fail("unexpected header line '" + std::string(w[0].substr(0, 40)) + "'");
    }
  }
  if (!format) in.fail("no 'format' line in the header");
  return header;
}

// Reads the values of the body, text or binary.
class PlyValues {
 public:
  PlyValues(MeshScanner& in, PlyEncoding encoding) : in_(in), encoding_(encoding) {}

  double read(PlyType type) {
    if (encoding_ == PlyEncoding::Ascii)
      return type.kind == 'f' ? in_.real()
                              : static_cast<double>(in_.number<std::int64_t>("an integer"));
    return in_.rawNumber(type, encoding_ == PlyEncoding::LittleEndian ? std::endian::little
                                                                       : std::endian::big);
  }

  // A list's count or index: an integer.
  std::int64_t integer(PlyType type) {
    const double v = read(type);
    if (v != std::floor(v)) in_.fail("expected an integer, found " + std::to_string(v));
    return static_cast<std::int64_t>(v);
  }

  // The fewest bytes (or characters) an item of `element` takes.
  std::size_t minimumSize(const PlyElement& element) const {
    std::size_t size = 0;
    for (const PlyProperty& p : element.properties)
      size += encoding_ == PlyEncoding::Ascii ? 2 : p.list ? p.countType.bytes : p.type.bytes;
    return size;
  }

 private:
  MeshScanner& in_;
  PlyEncoding encoding_;
};

bool isFaceList(const PlyElement& element, const PlyProperty& p) {
  return element.name == "face" && p.list &&
         (p.name == "vertex_indices" || p.name == "vertex_index");
}

// One item of `element`: vertex coordinates go to `xyz`, a face list to `faces`.
void readItem(MeshScanner& in, PlyValues& values, const PlyElement& element, std::uint64_t item,
              std::vector<double>& coords, PolygonFaces& faces) {
  const bool vertex = element.name == "vertex";
  double xyz[3] = {0, 0, 0};
  std::vector<std::int64_t> list;
  for (const PlyProperty& p : element.properties) {
    if (!p.list) {
      const double v = values.read(p.type);
      if (vertex && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z')
        xyz[p.name[0] - 'x'] = v;
      continue;
    }
    const std::int64_t n = values.integer(p.countType);
    if (n < 0 || static_cast<std::uint64_t>(n) > in.remaining())
      in.fail("a list of " + std::to_string(n) + " values");
    if (!isFaceList(element, p)) {
      for (std::int64_t k = 0; k < n; ++k) values.read(p.type);
      continue;
    }
    list.clear();
    for (std::int64_t k = 0; k < n; ++k) list.push_back(values.integer(p.type));
    faces.add(list, item);
  }
  if (vertex) coords.insert(coords.end(), xyz, xyz + 3);
}

void checkVertexProperties(MeshScanner& in, const PlyElement& element) {
  for (char axis : {'x', 'y', 'z'}) {
    bool found = false;
    for (const PlyProperty& p : element.properties)
      found = found || (!p.list && p.name == std::string(1, axis));
    if (!found) in.fail("the vertex element has no '" + std::string(1, axis) + "' property");
  }
}

void readBody(MeshScanner& in, const PlyHeader& header, Mesh& mesh) {
  std::uint64_t vertices = 0;
  for (const PlyElement& e : header.elements)
    if (e.name == "vertex") vertices = e.count;
  PolygonFaces faces(in, vertices);
  PlyValues values(in, header.encoding);
  std::vector<double> coords;
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex") checkVertexProperties(in, element);
    const std::size_t itemSize = std::max<std::size_t>(values.minimumSize(element), 1);
    if (element.count > (in.remaining() + 1) / itemSize)
      in.fail("element " + element.name.substr(0, 40) + ": " + std::to_string(element.count) +
              " items exceed the size of the file");
    for (std::uint64_t i = 0; i < element.count; ++i)
      readItem(in, values, element, i, coords, faces);
  }
  mesh.reserveNodes(coords.size() / 3);
  for (std::size_t i = 0; i < coords.size(); i += 3)
    mesh.addNode({coords[i], coords[i + 1], coords[i + 2]});
  faces.moveInto(mesh);
}

}  // namespace

// Named by the ply row of io/formats.cpp.
void readPly(std::istream& in, Model& model, Mesh& mesh, const std::string& name) {
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  readReplacing(model, mesh, [&] {
    MeshScanner scanner(data, name);
    readBody(scanner, readHeader(scanner), mesh);
    addDiscreteEntities(model, mesh);
  });
}

}  // namespace geomesh
