// XAO files: the OpenCASCADE shape as BREP text inside XML, with its entities and their tags.
#include "kernel/occ/occ_xao.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pnt.hxx>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kernel/geometry_error.h"

namespace geomesh {

namespace {

constexpr const char* kElements[4] = {"vertex", "edge", "face", "solid"};
constexpr const char* kLists[4] = {"vertices", "edges", "faces", "solids"};

// "part" for "dir/part.geo_unrolled.xao", as the geometry's name.
std::string geometryName(const std::string& path) {
  const std::string file = std::filesystem::path(path).filename().string();
  return file.substr(0, file.find('.'));
}

// The value of attribute `name` in the element text `element`, or "" when absent.
std::string attribute(const std::string& element, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t at = element.find(key);
  if (at == std::string::npos) return "";
  const std::size_t begin = at + key.size();
  const std::size_t end = element.find('"', begin);
  return end == std::string::npos ? "" : element.substr(begin, end - begin);
}

// A vertex's point to the last bit: the BREP text keeps 15 digits of it only.
std::string exactPoint(const TopoDS_Shape& vertex) {
  const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertex));
  char text[96];
  std::snprintf(text, sizeof text, "%.17g %.17g %.17g", p.X(), p.Y(), p.Z());
  return text;
}

// An edge's parameter range to the last bit, for the same reason.
std::string exactRange(const TopoDS_Shape& edge) {
  double first = 0, last = 0;
  BRep_Tool::Range(TopoDS::Edge(edge), first, last);
  char text[64];
  std::snprintf(text, sizeof text, "%.17g %.17g", first, last);
  return text;
}

// Puts back the exact points of the vertices and ranges of the edges that list them.
void restoreExactValues(const XaoEntity& e, const std::string& element) {
  double x = 0, y = 0, z = 0;
  if (e.dim == 0 &&
      std::sscanf(attribute(element, "coordinates").c_str(), "%lf %lf %lf", &x, &y, &z) == 3) {
    const TopoDS_Vertex vertex = TopoDS::Vertex(e.shape);
    BRep_Builder().UpdateVertex(vertex, gp_Pnt(x, y, z), BRep_Tool::Tolerance(vertex));
  }
  if (e.dim == 1 && std::sscanf(attribute(element, "range").c_str(), "%lf %lf", &x, &y) == 2 &&
      !BRep_Tool::Degenerated(TopoDS::Edge(e.shape)))
    BRep_Builder().Range(TopoDS::Edge(e.shape), x, y);
}

void writeTopology(const OccShapes& shapes, const TopTools_IndexedMapOfShape& all,
                   std::ostream& out) {
  out << "    <topology>\n";
  for (int dim = 0; dim <= 3; ++dim) {
    out << "      <" << kLists[dim] << " count=\"" << shapes.byTag[dim].size() << "\">\n";
    int index = 0;
    for (const auto& [tag, shape] : shapes.byTag[dim]) {
      out << "        <" << kElements[dim] << " index=\"" << index++ << "\" name=\"\" reference=\""
          << all.FindIndex(shape) << "\" tag=\"" << tag << "\"";
      if (dim == 0) out << " coordinates=\"" << exactPoint(shape) << "\"";
      if (dim == 1) out << " range=\"" << exactRange(shape) << "\"";
      out << "/>\n";
    }
    out << "      </" << kLists[dim] << ">\n";
  }
  out << "    </topology>\n";
}

void writeDocument(const OccShapes& shapes, const TopoDS_Shape& compound, const std::string& path,
                   std::ostream& out) {
  TopTools_IndexedMapOfShape all;
  TopExp::MapShapes(compound, all);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<XAO version=\"1.0\" author=\"geomesh\">\n"
      << "  <geometry name=\"" << geometryName(path) << "\">\n"
      << "    <shape format=\"BREP\"><![CDATA[";
  // Version 1 of the BREP text, without triangulations: what every OpenCASCADE release reads.
  BRepTools::Write(compound, out, false, false, TopTools_FormatVersion_VERSION_1);
  out << "]]></shape>\n";
  writeTopology(shapes, all, out);
  out << "  </geometry>\n  <groups count=\"0\">\n  </groups>\n  <fields count=\"0\"/>\n</XAO>\n";
}

int integer(const std::string& text) {
  try {
    return text.empty() ? 0 : std::stoi(text);
  } catch (const std::exception&) {
    return 0;
  }
}

// The entities the topology section lists, their sub-shapes found by index in `all`.
std::vector<XaoEntity> readTopology(const std::string& text, const TopTools_IndexedMapOfShape& all,
                                    const std::string& path) {
  std::vector<XaoEntity> entities;
  for (int dim = 0; dim <= 3; ++dim) {
    const std::string open = std::string("<") + kElements[dim] + " ";
    for (std::size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
      const std::size_t end = text.find('>', at);
      if (end == std::string::npos) break;
      const std::string element = text.substr(at, end - at);
      const int reference = integer(attribute(element, "reference"));
      if (reference < 1 || reference > all.Extent())
        throw GeometryError("'" + path + "': an XAO " + kElements[dim] +
                            " names no sub-shape of the BREP shape");
      entities.push_back({dim, integer(attribute(element, "tag")), all.FindKey(reference)});
      restoreExactValues(entities.back(), element);
    }
  }
  return entities;
}

// The <group> elements: dimension, tag, name and elements, each element an index into the
// topology's list of that dimension.
std::vector<XaoGroup> readGroups(const std::string& text, const std::vector<XaoEntity>& entities) {
  std::vector<const XaoEntity*> byIndex[4];
  for (const XaoEntity& e : entities) byIndex[e.dim].push_back(&e);
  std::vector<XaoGroup> groups;
  for (std::size_t at = text.find("<group "); at != std::string::npos;
       at = text.find("<group ", at + 1)) {
    const std::size_t open = text.find('>', at);
    const std::size_t close = text.find("</group>", at);
    if (open == std::string::npos) break;
    const std::string head = text.substr(at, open - at);
    const std::string kind = attribute(head, "dimension");
    int dim = -1;
    for (int d = 0; d <= 3; ++d)
      if (kind == kElements[d]) dim = d;
    if (dim < 0) continue;
    XaoGroup group{dim, integer(attribute(head, "tag")), attribute(head, "name"), {}};
    const std::string body = text.substr(open, close == std::string::npos ? 0 : close - open);
    for (std::size_t e = body.find("<element "); e != std::string::npos;
         e = body.find("<element ", e + 1)) {
      const int index = integer(attribute(body.substr(e, body.find('>', e) - e), "index"));
      if (index >= 0 && static_cast<std::size_t>(index) < byIndex[dim].size())
        group.elements.push_back(byIndex[dim][static_cast<std::size_t>(index)]->shape);
    }
    groups.push_back(std::move(group));
  }
  return groups;
}

}  // namespace

void writeXao(const OccShapes& shapes, const TopoDS_Shape& compound, const std::string& path) {
  const std::string temporary = path + ".part";
  {
    std::ofstream out(temporary);
    if (!out) throw GeometryError("cannot write '" + path + "'");
    writeDocument(shapes, compound, path, out);
    out.flush();
    if (!out) {
      out.close();
      std::filesystem::remove(temporary);
      throw GeometryError("cannot write '" + path + "'");
    }
  }
  std::error_code failed;
  std::filesystem::rename(temporary, path, failed);
  if (failed) {
    std::filesystem::remove(temporary);
    throw GeometryError("cannot write '" + path + "': " + failed.message());
  }
}

XaoContents readXao(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw GeometryError("cannot open '" + path + "'");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::size_t shapeAt = text.find("<shape");
  const std::size_t begin = text.find("<![CDATA[", shapeAt);
  const std::size_t end = text.find("]]>", begin);
  if (text.find("<XAO") == std::string::npos || shapeAt == std::string::npos ||
      begin == std::string::npos || end == std::string::npos)
    throw GeometryError("'" + path + "' is not an XAO file with a BREP shape");
  if (attribute(text.substr(shapeAt, text.find('>', shapeAt) - shapeAt), "format") != "BREP")
    throw GeometryError("'" + path + "': only XAO files holding a BREP shape are read");
  XaoContents contents;
  std::istringstream brep(text.substr(begin + 9, end - begin - 9));
  BRep_Builder builder;
  BRepTools::Read(contents.shape, brep, builder);
  if (contents.shape.IsNull())
    throw GeometryError("'" + path + "': its BREP shape cannot be read");
  TopTools_IndexedMapOfShape all;
  TopExp::MapShapes(contents.shape, all);
  contents.entities = readTopology(text.substr(end), all, path);
  contents.groups = readGroups(text.substr(end), contents.entities);
  return contents;
}

}  // namespace geomesh
