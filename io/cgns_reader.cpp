// CGNS (.cgns) read through libcgns: the first base, each of its unstructured zones (nodes kept
// apart per zone), every element section of the types io/cgns_elements.h lists (MIXED ones
// too), and the boundary conditions, whose families name physical groups.
#include <cgnslib.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "io/cgns_elements.h"
#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/mesh_scanner.h"

namespace geomesh {

namespace {

using CgnsType = CGNS_ENUMT(ElementType_t);

// An open CGNS file whose failures are MeshReadErrors naming it; closed on every path out.
class CgnsInput {
 public:
  explicit CgnsInput(const std::string& path) : name_(path) {
    if (cg_open(path.c_str(), CG_MODE_READ, &fn_) != CG_OK) {
      fn_ = -1;
      fail("cannot read it as CGNS: " + std::string(cg_get_error()));
    }
  }
  ~CgnsInput() {
    if (fn_ >= 0) cg_close(fn_);
  }
  CgnsInput(const CgnsInput&) = delete;
  CgnsInput& operator=(const CgnsInput&) = delete;

  int fn() const { return fn_; }
  void check(int status, const std::string& what) const {
    if (status != CG_OK) fail(what + ": " + cg_get_error());
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw MeshReadError(name_ + ": " + message);
  }

 private:
  std::string name_;
  int fn_ = -1;
};

// One element section, its nodes already numbered in the mesh and put in MSH order.
struct CgnsSection {
  std::string name;
  cgsize_t first = 0;
  std::vector<const CgnsElement*> elements;
  std::vector<NodeIndex> nodes;  // the elements' nodes one after the other
  std::vector<int> group;        // per element: index of its group name, -1 for none
};

struct CgnsZoneContent {
  std::vector<CgnsSection> sections;
};

// What is read from the file before the mesh gets its entities.
struct CgnsContent {
  int cellDim = 0;
  std::map<std::string, std::string> familyGroups;  // family -> the group name it holds
  std::vector<std::string> groupNames;
  std::vector<CgnsZoneContent> zones;

  int groupIndex(const std::string& name) {
    const auto found = std::find(groupNames.begin(), groupNames.end(), name);
    if (found != groupNames.end()) return static_cast<int>(found - groupNames.begin());
    groupNames.push_back(name);
    return static_cast<int>(groupNames.size()) - 1;
  }
};

// Where one zone is in the file, and where its nodes start in the mesh.
struct ZoneAt {
  const CgnsInput& in;
  int base = 0, zone = 0;
  std::string name;
  cgsize_t vertices = 0;
  NodeIndex firstNode = 0;

  std::string what(const std::string& text) const { return "zone '" + name + "': " + text; }
  [[noreturn]] void fail(const std::string& text) const { in.fail(what(text)); }
};

// A family's group name: the family name it carries (as the reference's files write), else its
// own name.
void readFamilies(const CgnsInput& in, int base, CgnsContent& content) {
  int families = 0;
  in.check(cg_nfamilies(in.fn(), base, &families), "families");
  for (int f = 1; f <= families; ++f) {
    char name[33] = "", node[33] = "", family[33] = "";
    int bcs = 0, geometries = 0, names = 0;
    in.check(cg_family_read(in.fn(), base, f, name, &bcs, &geometries), "family");
    in.check(cg_nfamily_names(in.fn(), base, f, &names), "family names");
    if (names > 0) in.check(cg_family_name_read(in.fn(), base, f, 1, node, family), "family name");
    content.familyGroups[name] = family[0] ? family : node[0] ? node : name;
  }
}

void readCoordinates(const ZoneAt& z, Mesh& mesh) {
  int count = 0;
  z.in.check(cg_ncoords(z.in.fn(), z.base, z.zone, &count), z.what("coordinates"));
  std::vector<double> axes[3];
  const std::string names[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
  const cgsize_t first = 1, last = z.vertices;
  for (int c = 1; c <= count; ++c) {
    CGNS_ENUMT(DataType_t) type;
    char name[33] = "";
    z.in.check(cg_coord_info(z.in.fn(), z.base, z.zone, c, &type, name), z.what("coordinates"));
    const auto axis = std::find(std::begin(names), std::end(names), name) - std::begin(names);
    if (axis == 3) z.fail("coordinate '" + std::string(name) + "' is not Cartesian");
    axes[axis].resize(static_cast<std::size_t>(z.vertices));
    z.in.check(cg_coord_read(z.in.fn(), z.base, z.zone, name, CGNS_ENUMV(RealDouble), &first, &last,
                             axes[axis].data()),
               z.what("coordinates"));
  }
  if (axes[0].empty() && z.vertices > 0) z.fail("no CoordinateX");
  for (std::size_t n = 0; n < static_cast<std::size_t>(z.vertices); ++n) {
    const Vec3 p{axes[0][n], axes[1].empty() ? 0 : axes[1][n], axes[2].empty() ? 0 : axes[2][n]};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      z.fail("node " + std::to_string(n + 1) + " has a non-finite coordinate");
    mesh.addNode(p);
  }
}

const CgnsElement& elementOf(const ZoneAt& z, const std::string& section, CgnsType type) {
  const CgnsElement* element = cgnsElementFor(type);
  if (!element)
    z.fail("section '" + section + "': CGNS elements of type " + cg_ElementTypeName(type) +
           " are not supported");
  return *element;
}

// Appends one element whose CGNS node numbers are `numbers`.
void addElement(const ZoneAt& z, CgnsSection& s, const CgnsElement& element,
                std::span<const cgsize_t> numbers) {
  if (numbers.size() != element.fromMsh.size())
    z.fail("section '" + s.name + "': element " + std::to_string(s.elements.size() + 1) + " has " +
           std::to_string(numbers.size()) + " nodes");
  const std::size_t at = s.nodes.size();
  s.nodes.resize(at + numbers.size());
  for (std::size_t k = 0; k < numbers.size(); ++k) {
    if (numbers[k] < 1 || numbers[k] > z.vertices)
      z.fail("section '" + s.name + "': node " + std::to_string(numbers[k]) + " does not exist (" +
             std::to_string(z.vertices) + " nodes)");
    s.nodes[at + element.fromMsh[k]] = z.firstNode + static_cast<NodeIndex>(numbers[k] - 1);
  }
  s.elements.push_back(&element);
}

void readMixedElements(const ZoneAt& z, int index, CgnsSection& s, cgsize_t count, cgsize_t size) {
  std::vector<cgsize_t> data(static_cast<std::size_t>(size));
  std::vector<cgsize_t> offsets(static_cast<std::size_t>(count) + 1);
  z.in.check(
      cg_poly_elements_read(z.in.fn(), z.base, z.zone, index, data.data(), offsets.data(), nullptr),
      z.what("elements of section '" + s.name + "'"));
  for (std::size_t e = 0; e < static_cast<std::size_t>(count); ++e) {
    const cgsize_t begin = offsets[e], end = offsets[e + 1];
    if (begin < 0 || end <= begin || end > size)
      z.fail("section '" + s.name + "': bad offsets of element " + std::to_string(e + 1));
    const auto type = static_cast<CgnsType>(data[begin]);
    addElement(z, s, elementOf(z, s.name, type),
               std::span<const cgsize_t>(data).subspan(begin + 1, end - begin - 1));
  }
}

CgnsSection readSection(const ZoneAt& z, int index) {
  CgnsSection s;
  char name[33] = "";
  CgnsType type;
  cgsize_t first = 0, last = 0, size = 0;
  int boundaries = 0, parents = 0;
  z.in.check(cg_section_read(z.in.fn(), z.base, z.zone, index, name, &type, &first, &last,
                             &boundaries, &parents),
             z.what("element section " + std::to_string(index)));
  s.name = name;
  s.first = first;
  const cgsize_t count = last - first + 1;
  if (first < 1 || count < 0) z.fail("section '" + s.name + "': bad element range");
  z.in.check(cg_ElementDataSize(z.in.fn(), z.base, z.zone, index, &size),
             z.what("size of section '" + s.name + "'"));
  if (size < 0) z.fail("section '" + s.name + "': bad size");
  if (type == CGNS_ENUMV(MIXED)) {
    readMixedElements(z, index, s, count, size);
  } else {
    const CgnsElement& element = elementOf(z, s.name, type);
    const auto npe = static_cast<cgsize_t>(element.fromMsh.size());
    if (size != count * npe) z.fail("section '" + s.name + "': size does not match its range");
    std::vector<cgsize_t> data(static_cast<std::size_t>(size));
    z.in.check(cg_elements_read(z.in.fn(), z.base, z.zone, index, data.data(), nullptr),
               z.what("elements of section '" + s.name + "'"));
    for (cgsize_t e = 0; e < count; ++e)
      addElement(z, s, element, std::span<const cgsize_t>(data).subspan(e * npe, npe));
  }
  s.group.assign(s.elements.size(), -1);
  return s;
}

// The group of a boundary condition: its family's group name, else its own name.
std::string boundaryGroupName(const ZoneAt& z, int bc, const std::string& name,
                              const CgnsContent& content) {
  char family[33] = "";
  if (cg_goto(z.in.fn(), z.base, "Zone_t", z.zone, "ZoneBC_t", 1, "BC_t", bc, "end") != CG_OK ||
      cg_famname_read(family) != CG_OK || !family[0])
    return name;
  const auto found = content.familyGroups.find(family);
  return found == content.familyGroups.end() ? family : found->second;
}

// The numbers a point set names (a list, or a range of two), leaving out those outside
// [1, last].
std::vector<cgsize_t> pointSetNumbers(const std::vector<cgsize_t>& numbers, bool range,
                                      long long last) {
  std::vector<cgsize_t> out;
  if (!range) {
    for (cgsize_t n : numbers)
      if (n >= 1 && n <= last) out.push_back(n);
  } else if (numbers.size() == 2) {
    for (long long n = std::max<long long>(numbers[0], 1);
         n <= std::min<long long>(numbers[1], last); ++n)
      out.push_back(static_cast<cgsize_t>(n));
  }
  return out;
}

// Gives the elements numbered in `numbers` group `group`, unless they have one.
void markElements(CgnsZoneContent& zone, const std::vector<cgsize_t>& numbers, bool range,
                  int group) {
  long long last = 0;
  for (const CgnsSection& s : zone.sections)
    last = std::max<long long>(last, s.first + static_cast<long long>(s.group.size()) - 1);
  for (cgsize_t number : pointSetNumbers(numbers, range, last))
    for (CgnsSection& s : zone.sections) {
      const long long i = number - s.first;
      if (i >= 0 && i < static_cast<long long>(s.group.size()) && s.group[i] < 0)
        s.group[i] = group;
    }
}

// Gives the elements of dimension `dim` whose nodes are all among `numbers` (vertices of the
// zone) group `group`, unless they have one.
void markElementsOnNodes(const ZoneAt& z, CgnsZoneContent& zone,
                         const std::vector<cgsize_t>& numbers, bool range, int dim, int group) {
  std::set<NodeIndex> nodes;
  for (cgsize_t n : pointSetNumbers(numbers, range, z.vertices))
    nodes.insert(z.firstNode + static_cast<NodeIndex>(n - 1));
  for (CgnsSection& s : zone.sections) {
    std::size_t at = 0;
    for (std::size_t e = 0; e < s.elements.size(); ++e) {
      const std::size_t n = s.elements[e]->fromMsh.size();
      const bool inside = std::all_of(s.nodes.begin() + at, s.nodes.begin() + at + n,
                                      [&](NodeIndex v) { return nodes.count(v) > 0; });
      if (inside && dimension(s.elements[e]->type) == dim && s.group[e] < 0) s.group[e] = group;
      at += n;
    }
  }
}

void readBoundary(const ZoneAt& z, int bc, CgnsZoneContent& zone, CgnsContent& content) {
  char name[33] = "";
  CGNS_ENUMT(BCType_t) type;
  CGNS_ENUMT(PointSetType_t) pointSet;
  CGNS_ENUMT(DataType_t) normalType;
  CGNS_ENUMT(GridLocation_t) location;
  cgsize_t count = 0, normalSize = 0;
  int normalIndex[3] = {0, 0, 0}, datasets = 0;
  z.in.check(cg_boco_info(z.in.fn(), z.base, z.zone, bc, name, &type, &pointSet, &count,
                          normalIndex, &normalSize, &normalType, &datasets),
             z.what("boundary condition " + std::to_string(bc)));
  if (count < 0) z.fail("boundary condition '" + std::string(name) + "': bad size");
  std::vector<cgsize_t> numbers(static_cast<std::size_t>(count));
  z.in.check(cg_boco_read(z.in.fn(), z.base, z.zone, bc, numbers.data(), nullptr),
             z.what("boundary condition '" + std::string(name) + "'"));
  z.in.check(cg_boco_gridlocation_read(z.in.fn(), z.base, z.zone, bc, &location),
             z.what("boundary condition '" + std::string(name) + "'"));
  const int group = content.groupIndex(boundaryGroupName(z, bc, name, content));
  const bool range = pointSet == CGNS_ENUMV(PointRange) || pointSet == CGNS_ENUMV(ElementRange);
  const bool onNodes = location == CGNS_ENUMV(Vertex) && pointSet != CGNS_ENUMV(ElementList) &&
                       pointSet != CGNS_ENUMV(ElementRange) && content.cellDim > 1;
  // Vertex lists name the nodes of boundary elements; geomesh's own 1D files list elements.
  if (onNodes)
    markElementsOnNodes(z, zone, numbers, range, content.cellDim - 1, group);
  else
    markElements(zone, numbers, range, group);
}

void readZone(ZoneAt z, CgnsContent& content, Mesh& mesh) {
  char name[33] = "";
  cgsize_t size[9] = {};
  CGNS_ENUMT(ZoneType_t) type;
  z.in.check(cg_zone_read(z.in.fn(), z.base, z.zone, name, size), "zone " + std::to_string(z.zone));
  z.name = name;
  z.in.check(cg_zone_type(z.in.fn(), z.base, z.zone, &type), z.what("zone type"));
  if (type != CGNS_ENUMV(Unstructured)) z.fail("structured CGNS zones are not supported");
  if (size[0] < 0) z.fail("bad vertex count");
  z.vertices = size[0];
  z.firstNode = static_cast<NodeIndex>(mesh.nodeCount());
  readCoordinates(z, mesh);
  CgnsZoneContent& zone = content.zones.emplace_back();
  int sections = 0, boundaries = 0;
  z.in.check(cg_nsections(z.in.fn(), z.base, z.zone, &sections), z.what("sections"));
  for (int s = 1; s <= sections; ++s) zone.sections.push_back(readSection(z, s));
  z.in.check(cg_nbocos(z.in.fn(), z.base, z.zone, &boundaries), z.what("boundary conditions"));
  for (int bc = 1; bc <= boundaries; ++bc) readBoundary(z, bc, zone, content);
}

// One entity per zone, section, dimension and group; with groups in the file, the elements
// outside every group get one named after their section, so that saving keeps them.
std::vector<PhysicalGroup> addEntities(const CgnsContent& content, Mesh& mesh) {
  std::map<std::tuple<std::size_t, std::size_t, int, int>, EntityId> entities;
  std::map<std::pair<int, std::string>, PhysicalGroup> groups;
  int nextTag[4] = {1, 1, 1, 1};
  std::map<int, int> nextGroupTag;
  const bool grouped = !content.groupNames.empty();
  for (std::size_t z = 0; z < content.zones.size(); ++z)
    for (std::size_t s = 0; s < content.zones[z].sections.size(); ++s) {
      const CgnsSection& section = content.zones[z].sections[s];
      std::size_t at = 0;
      for (std::size_t e = 0; e < section.elements.size(); ++e) {
        const CgnsElement& element = *section.elements[e];
        const int dim = dimension(element.type);
        const int g = section.group[e];
        auto [it, added] = entities.try_emplace({z, s, dim, g}, EntityId{dim, nextTag[dim]});
        if (added) {
          ++nextTag[dim];
          if (g >= 0 || grouped) {
            const std::string name = g >= 0 ? content.groupNames[g] : section.name;
            auto [group, created] = groups.try_emplace({dim, name});
            if (created) group->second = {dim, ++nextGroupTag[dim], name, {}};
            group->second.entities.push_back(it->second.tag);
          }
        }
        const std::size_t n = element.fromMsh.size();
        ElementBlock& block = mesh.entity(it->second).block(element.type);
        block.nodes.insert(block.nodes.end(), section.nodes.begin() + at,
                           section.nodes.begin() + at + n);
        at += n;
      }
    }
  std::vector<PhysicalGroup> result;
  for (auto& [key, group] : groups) result.push_back(std::move(group));
  return result;
}

}  // namespace

// Named by the cgns row of io/formats.cpp, as its path reader. Reads the first base only.
void readCgns(const std::string& path, Model& model, Mesh& mesh) {
  readReplacing(model, mesh, [&] {
    CgnsInput in(path);
    int bases = 0, zones = 0, physicalDim = 0;
    in.check(cg_nbases(in.fn(), &bases), "bases");
    if (bases < 1) in.fail("no CGNS base");
    CgnsContent content;
    char baseName[33] = "";
    in.check(cg_base_read(in.fn(), 1, baseName, &content.cellDim, &physicalDim), "base");
    readFamilies(in, 1, content);
    in.check(cg_nzones(in.fn(), 1, &zones), "zones");
    for (int z = 1; z <= zones; ++z) readZone(ZoneAt{in, 1, z, "", 0, 0}, content, mesh);
    addDiscreteEntities(model, mesh, addEntities(content, mesh));
  });
}

}  // namespace geomesh
