// Legacy VTK reader: UNSTRUCTURED_GRID and POLYDATA datasets, ASCII or binary (big-endian), in
// the classic cell lists or VTK 5's OFFSETS/CONNECTIVITY. Cells become elements of discrete
// entities, tagged by a cell data array (CellEntityIds, gmsh:geometrical, else the first integer
// one; gmsh:physical gives physical groups) or, without one, one entity per dimension.
#include <algorithm>
#include <array>
#include <cmath>
#include <istream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <string>

#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/vtk_arrays.h"
#include "io/vtk_cells.h"

namespace geomesh {

namespace {

// Cells as VTK lists them: cell i's nodes are connectivity[offsets[i] .. offsets[i + 1]).
struct VtkCellList {
  std::vector<std::int64_t> offsets{0};
  std::vector<std::int64_t> connectivity;
  std::vector<int> types;
  int line = 0;       // where the list starts, for errors
  int typesLine = 0;  // where CELL_TYPES starts
};

struct VtkData {
  bool polydata = false;
  std::vector<double> points;
  VtkCellList cells;
  // POLYDATA: vertices, lines, polygons and strips, numbered in that order as VTK does.
  std::array<VtkCellList, 4> parts;
  std::vector<VtkCellArray> cellArrays;
};

constexpr int kPolyVertex = 2, kPolyLine = 4, kTriangleStrip = 6, kPolygon = 7;

// The four header lines; returns whether the data is binary, and sets data.polydata.
bool readHeader(MeshScanner& in, VtkData& data) {
  if (!lowercase(in.line()).starts_with("# vtk datafile version"))
    in.fail("not a legacy VTK file: no '# vtk DataFile Version' line", 1);
  in.line();  // the title
  const std::string encoding = lowercase(in.line());
  if (encoding != "ascii" && encoding != "binary")
    in.fail("expected ASCII or BINARY, found '" + encoding.substr(0, 40) + "'");
  if (in.word() != "DATASET") in.fail("expected DATASET");
  const std::string_view dataset = in.word();
  if (dataset != "UNSTRUCTURED_GRID" && dataset != "POLYDATA")
    in.fail("unsupported dataset " + std::string(dataset.substr(0, 40)) +
            " (UNSTRUCTURED_GRID and POLYDATA are read)");
  data.polydata = dataset == "POLYDATA";
  return encoding == "binary";
}

// A classic list: per cell its node count, then its nodes.
void readClassicList(VtkArrayReader& in, VtkCellList& list, std::uint64_t cells,
                     std::uint64_t size) {
  std::vector<std::int64_t> values;
  in.read("int", size, values);
  std::size_t at = 0;
  for (std::uint64_t i = 0; i < cells; ++i) {
    if (at >= values.size() || values[at] < 0 ||
        static_cast<std::uint64_t>(values[at]) > values.size() - at - 1)
      in.scanner().fail("cell " + std::to_string(i) + " runs past the end of its list", list.line);
    list.connectivity.insert(list.connectivity.end(), values.begin() + at + 1,
                             values.begin() + at + 1 + values[at]);
    at += 1 + values[at];
    list.offsets.push_back(static_cast<std::int64_t>(list.connectivity.size()));
  }
  if (at != values.size())
    in.scanner().fail("the cell list has " + std::to_string(size) + " numbers, not " +
                      std::to_string(at), list.line);
}

// VTK 5: OFFSETS (cells + 1 values, from 0) and CONNECTIVITY.
void readOffsetList(VtkArrayReader& in, VtkCellList& list, std::uint64_t offsets,
                    std::uint64_t size) {
  MeshScanner& s = in.scanner();
  s.word();
  const std::string offsetType(s.word());
  s.line();
  list.offsets.clear();
  in.read(offsetType, offsets, list.offsets);
  if (s.word() != "CONNECTIVITY") s.fail("expected CONNECTIVITY");
  const std::string type(s.word());
  s.line();
  in.read(type, size, list.connectivity);
  if (list.offsets.empty() || list.offsets.front() != 0 ||
      list.offsets.back() != static_cast<std::int64_t>(size) ||
      !std::is_sorted(list.offsets.begin(), list.offsets.end()))
    s.fail("the cell offsets do not run from 0 to " + std::to_string(size), list.line);
}

// "CELLS n size" and the like, whose keyword has been read.
void readCellList(VtkArrayReader& in, VtkCellList& list) {
  MeshScanner& s = in.scanner();
  list.line = s.lineNumber();
  const std::uint64_t n = in.count("a cell count", 4);
  const std::uint64_t size = in.count("a cell list size", 4);
  s.line();
  if (in.nextIs("OFFSETS"))
    readOffsetList(in, list, n, size);
  else
    readClassicList(in, list, n, size);
}

// The type of each cell of a POLYDATA part, from its node count.
void typePolydataPart(VtkCellList& list, int part) {
  for (std::size_t i = 0; i + 1 < list.offsets.size(); ++i) {
    const std::int64_t n = list.offsets[i + 1] - list.offsets[i];
    const int byPart[4] = {n == 1 ? 1 : kPolyVertex, n == 2 ? 3 : kPolyLine, kPolygon,
                           kTriangleStrip};
    list.types.push_back(byPart[part]);
  }
}

void readCellTypes(VtkArrayReader& in, VtkCellList& list) {
  list.typesLine = in.scanner().lineNumber();
  const std::uint64_t n = in.count("a cell count", 4);
  in.scanner().line();
  std::vector<std::int64_t> types;
  in.read("int", n, types);
  list.types.assign(types.begin(), types.end());
}

void appendList(VtkCellList& to, const VtkCellList& from) {
  const std::int64_t base = to.offsets.back();
  for (std::size_t i = 1; i < from.offsets.size(); ++i)
    to.offsets.push_back(base + from.offsets[i]);
  to.connectivity.insert(to.connectivity.end(), from.connectivity.begin(), from.connectivity.end());
  to.types.insert(to.types.end(), from.types.begin(), from.types.end());
  if (to.line == 0) to.line = from.line;
}

// Reads one section, whose keyword has been read; false when the keyword is unknown.
bool readSection(VtkArrayReader& in, VtkData& data, std::string_view keyword) {
  static constexpr std::string_view kParts[] = {"VERTICES", "LINES", "POLYGONS",
                                                "TRIANGLE_STRIPS"};
  MeshScanner& s = in.scanner();
  if (keyword == "POINTS") {
    const std::uint64_t n = in.count("a point count", 12);
    const std::string type(s.word());
    s.line();
    in.read(type, 3 * n, data.points);
  } else if (keyword == "CELLS" && !data.polydata) {
    readCellList(in, data.cells);
  } else if (keyword == "CELL_TYPES" && !data.polydata) {
    readCellTypes(in, data.cells);
  } else if (const auto* part = std::find(std::begin(kParts), std::end(kParts), keyword);
             data.polydata && part != std::end(kParts)) {
    const int index = static_cast<int>(part - std::begin(kParts));
    readCellList(in, data.parts[index]);
    typePolydataPart(data.parts[index], index);
  } else if (keyword == "CELL_DATA" || keyword == "POINT_DATA") {
    const std::uint64_t n = in.count("a count", 1);
    in.readAttributes(n, keyword == "CELL_DATA" ? &data.cellArrays : nullptr);
  } else if (keyword == "FIELD") {
    in.readField(nullptr, 0);
  } else if (keyword == "METADATA") {
    in.skipMetadata();
  } else {
    return false;
  }
  return true;
}

VtkData readData(MeshScanner& s) {
  VtkData data;
  VtkArrayReader in(s, readHeader(s, data));
  while (!s.atEnd()) {
    const int line = s.lineNumber();
    const std::string keyword(s.word());
    if (!readSection(in, data, keyword))
      s.fail("unexpected keyword '" + keyword.substr(0, 40) + "'", line);
  }
  if (data.polydata)
    for (const VtkCellList& part : data.parts) appendList(data.cells, part);
  const std::size_t cells = data.cells.offsets.size() - 1;
  if (data.cells.types.size() != cells)
    s.fail("the file has " + std::to_string(cells) + " cells and " +
               std::to_string(data.cells.types.size()) + " cell types",
           data.cells.typesLine);
  return data;
}

// Appends elements to the blocks of their entities, keeping the last block at hand.
class ElementSink {
 public:
  explicit ElementSink(Mesh& mesh) : mesh_(mesh) {}
  void add(ElementType type, int tag, std::span<const NodeIndex> nodes) {
    const EntityId entity{dimension(type), tag};
    if (!block_ || entity != entity_ || type != block_->type) {
      block_ = &mesh_.entity(entity).block(type);
      entity_ = entity;
    }
    block_->nodes.insert(block_->nodes.end(), nodes.begin(), nodes.end());
  }

 private:
  Mesh& mesh_;
  EntityId entity_;
  ElementBlock* block_ = nullptr;
};

// The tags of the cells: an entity array and a physical group array, either possibly absent.
struct CellTags {
  const VtkCellArray* entity = nullptr;
  const VtkCellArray* physical = nullptr;
};

const VtkCellArray* arrayNamed(const VtkData& data, std::string_view name, std::size_t cells) {
  for (const VtkCellArray& a : data.cellArrays)
    if (a.name == name && a.values.size() == cells) return &a;
  return nullptr;
}

CellTags chooseTags(const VtkData& data, std::size_t cells) {
  CellTags tags;
  tags.physical = arrayNamed(data, "gmsh:physical", cells);
  tags.entity = arrayNamed(data, "CellEntityIds", cells);
  if (!tags.entity) tags.entity = arrayNamed(data, "gmsh:geometrical", cells);
  for (const VtkCellArray& a : data.cellArrays)
    if (!tags.entity && a.integral && a.values.size() == cells && &a != tags.physical)
      tags.entity = &a;
  if (!tags.entity) std::swap(tags.entity, tags.physical);
  return tags;
}

int tagOf(const MeshScanner& in, const VtkCellArray* array, std::size_t cell) {
  if (!array) return 1;
  const double v = array->values[cell];
  if (v != std::floor(v) || v < 0 || v > std::numeric_limits<int>::max())
    in.fail("cell " + std::to_string(cell) + " has tag " + std::to_string(v) + " in '" +
                array->name + "': tags are integers from 0",
            array->line);
  return static_cast<int>(v);
}

// Adds the elements of cell `i` (several for VTK's poly-vertices, poly-lines and triangle
// strips) and returns their dimension, or -1 when the cell had none.
int addCell(const MeshScanner& in, const VtkCellList& list, std::size_t i, int tag,
            ElementSink& sink) {
  std::vector<NodeIndex> vtk(list.connectivity.begin() + list.offsets[i],
                             list.connectivity.begin() + list.offsets[i + 1]);
  const int type = list.types[i];
  const std::size_t n = vtk.size();
  if (type == kPolyVertex) {
    for (NodeIndex node : vtk) sink.add(ElementType::Point1, tag, {&node, 1});
    return n > 0 ? 0 : -1;
  }
  if (type == kPolyLine && n >= 2) {
    for (std::size_t k = 0; k + 1 < n; ++k) sink.add(ElementType::Line2, tag, {&vtk[k], 2});
    return 1;
  }
  if (type == kTriangleStrip && n >= 3) {
    for (std::size_t k = 0; k + 2 < n; ++k) {  // every other triangle turns the other way
      const std::array<NodeIndex, 3> t = {vtk[k + (k % 2)], vtk[k + 1 - (k % 2)], vtk[k + 2]};
      sink.add(ElementType::Triangle3, tag, t);
    }
    return 2;
  }
  const VtkLayout* layout = vtkLayoutForReading(type, n);
  if (!layout)
    in.fail("cell " + std::to_string(i) + ": " +
                (type == kPolygon ? "a polygon of " + std::to_string(n) +
                                        " nodes (triangles and quadrangles are read)"
                                  : "unsupported VTK cell type " + std::to_string(type) +
                                        " with " + std::to_string(n) + " nodes"),
            list.line);
  std::vector<NodeIndex> msh(n);
  for (std::size_t k = 0; k < n; ++k) msh[layout->fromMsh[k]] = vtk[k];
  sink.add(layout->type, tag, msh);
  return dimension(layout->type);
}

void checkNodes(const MeshScanner& in, const VtkCellList& list, std::size_t points) {
  for (std::int64_t node : list.connectivity)
    if (node < 0 || static_cast<std::uint64_t>(node) >= points)
      in.fail("a cell uses point " + std::to_string(node) + ", but the file has " +
                  std::to_string(points) + " points",
              list.line);
}

std::vector<PhysicalGroup> physicalGroups(const std::map<EntityId, std::set<int>>& members) {
  std::vector<PhysicalGroup> groups;
  for (const auto& [id, entities] : members)
    groups.push_back({id.dim, id.tag, "", std::vector<int>(entities.begin(), entities.end())});
  return groups;
}

void buildMesh(const MeshScanner& in, const VtkData& data, Model& model, Mesh& mesh) {
  const std::size_t points = data.points.size() / 3;
  if (points > std::numeric_limits<NodeIndex>::max()) in.fail("too many points");
  const VtkCellList& list = data.cells;
  checkNodes(in, list, points);
  mesh.reserveNodes(points);
  for (std::size_t p = 0; p < points; ++p)
    mesh.addNode({data.points[3 * p], data.points[3 * p + 1], data.points[3 * p + 2]});
  const std::size_t cells = list.types.size();
  const CellTags tags = chooseTags(data, cells);
  std::map<EntityId, std::set<int>> members;
  ElementSink sink(mesh);
  for (std::size_t i = 0; i < cells; ++i) {
    const int tag = tagOf(in, tags.entity, i);
    const int dim = addCell(in, list, i, tag, sink);
    if (!tags.physical || dim < 0) continue;
    if (const int group = tagOf(in, tags.physical, i); group > 0) members[{dim, group}].insert(tag);
  }
  addDiscreteEntities(model, mesh, physicalGroups(members));
}

}  // namespace

// Named by the vtk row of io/formats.cpp.
void readVtk(std::istream& in, Model& model, Mesh& mesh, const std::string& name) {
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  MeshScanner scanner(text, name);
  readReplacing(model, mesh, [&] { buildMesh(scanner, readData(scanner), model, mesh); });
}

}  // namespace geomesh
