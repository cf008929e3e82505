// CGNS (.cgns, HDF5) through libcgns: one base, one unstructured zone, its GridCoordinates, one
// element section per entity and element type (those of the top dimension first), and per
// physical group of the cells' dimension or the one below a family and a boundary condition
// listing its elements.
#include <cgnslib.h>

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/cgns_elements.h"
#include "io/cgns_summary.h"
#include "io/formats.h"
#include "io/msh_content.h"
#include "io/physical_sets.h"

namespace geomesh {

namespace {

// What the file holds, chosen and checked before it is opened.
struct CgnsPlan {
  int cellDim = 0;
  std::vector<std::size_t> sections;   // blocks of content.elementBlocks, top dimension first
  std::vector<cgsize_t> firstElement;  // per block of content.elementBlocks, from 1
  std::size_t cellCount = 0;
};

CgnsPlan planCgns(const MshContent& content) {
  CgnsPlan plan;
  for (const MshElementBlock& b : content.elementBlocks) {
    cgnsElementOf(b.block->type);
    plan.cellDim = std::max(plan.cellDim, dimension(b.block->type));
  }
  if (plan.cellDim == 0)
    throw std::invalid_argument("CGNS zones need elements of dimension 1 to 3");
  if (content.nodeCount > INT_MAX || content.elementCount > INT_MAX)
    throw std::invalid_argument("this CGNS library holds at most 2^31 - 1 nodes and elements");
  plan.firstElement.assign(content.elementBlocks.size(), 0);
  cgsize_t next = 1;
  for (int dim = plan.cellDim; dim >= 0; --dim)
    for (std::size_t i = 0; i < content.elementBlocks.size(); ++i) {
      const ElementBlock& block = *content.elementBlocks[i].block;
      if (dimension(block.type) != dim) continue;
      plan.sections.push_back(i);
      plan.firstElement[i] = next;
      next += static_cast<cgsize_t>(block.size());
      if (dim == plan.cellDim) plan.cellCount += block.size();
    }
  return plan;
}

void check(int status, const std::string& what) {
  if (status != CG_OK) throw std::runtime_error("CGNS " + what + ": " + cg_get_error());
}

// An open CGNS file, closed on every path out.
class CgnsFile {
 public:
  explicit CgnsFile(const std::string& path) {
    check(cg_set_file_type(CG_FILE_HDF5), "file type");
    check(cg_open(path.c_str(), CG_MODE_WRITE, &fn_), "cannot create '" + path + "'");
  }
  ~CgnsFile() {
    if (fn_ >= 0) cg_close(fn_);
  }
  CgnsFile(const CgnsFile&) = delete;
  CgnsFile& operator=(const CgnsFile&) = delete;

  void close() {
    const int fn = fn_;
    fn_ = -1;
    check(cg_close(fn), "close");
  }
  int fn() const { return fn_; }

 private:
  int fn_ = -1;
};

struct CgnsZone {
  int fn = 0, base = 0, zone = 0;
};

void writeCoordinates(const CgnsZone& z, const Mesh& mesh, const MshContent& content) {
  std::vector<double> xyz[3];
  for (const MshNodeBlock& block : content.nodeBlocks)
    for (NodeIndex n : block.nodes) {
      const Vec3 p = mesh.node(n);
      xyz[0].push_back(p.x);
      xyz[1].push_back(p.y);
      xyz[2].push_back(p.z);
    }
  const char* names[] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
  for (int k = 0; k < 3; ++k) {
    int index = 0;
    check(cg_coord_write(z.fn, z.base, z.zone, CGNS_ENUMV(RealDouble), names[k], xyz[k].data(),
                         &index),
          "coordinates");
  }
}

std::string sectionName(EntityId entity, const CgnsElement& element) {
  static constexpr const char* kWords[] = {"Point", "Curve", "Surface", "Volume"};
  return kWords[entity.dim] + std::to_string(entity.tag) + "_" +
         cg_ElementTypeName(static_cast<CGNS_ENUMT(ElementType_t)>(element.cgnsType));
}

void writeSections(const CgnsZone& z, const MshContent& content, const CgnsPlan& plan) {
  std::vector<cgsize_t> connectivity;
  for (std::size_t i : plan.sections) {
    const MshElementBlock& b = content.elementBlocks[i];
    const CgnsElement& element = cgnsElementOf(b.block->type);
    connectivity.clear();
    for (std::size_t e = 0; e < b.block->size(); ++e) {
      const auto nodes = b.block->element(e);
      for (int k : element.fromMsh)
        connectivity.push_back(static_cast<cgsize_t>(content.nodeTag[nodes[k]]));
    }
    const cgsize_t first = plan.firstElement[i];
    const cgsize_t last = first + static_cast<cgsize_t>(b.block->size()) - 1;
    const auto type = static_cast<CGNS_ENUMT(ElementType_t)>(element.cgnsType);
    int section = 0;
    check(cg_section_write(z.fn, z.base, z.zone, sectionName(b.entity, element).c_str(), type,
                           first, last, 0, connectivity.data(), &section),
          "element section");
  }
}

// Per physical group of the cells' dimension or of the boundary's: a family named after it,
// and a boundary condition of that family listing the group's elements (located at cell
// centres for groups of cells, as the reference writes them too).
void writeBoundaries(const CgnsZone& z, const Model& model, const MshContent& content,
                     const CgnsPlan& plan) {
  const auto boundaryLocation = plan.cellDim == 3   ? CGNS_ENUMV(FaceCenter)
                                : plan.cellDim == 2 ? CGNS_ENUMV(EdgeCenter)
                                                    : CGNS_ENUMV(Vertex);
  for (const auto& [id, group] : model.physicalGroups()) {
    if (group.dim != plan.cellDim - 1 && group.dim != plan.cellDim) continue;
    const auto location = group.dim == plan.cellDim ? CGNS_ENUMV(CellCenter) : boundaryLocation;
    std::vector<cgsize_t> elements;
    for (std::size_t i : groupBlocks(content, group))
      for (std::size_t e = 0; e < content.elementBlocks[i].block->size(); ++e)
        elements.push_back(plan.firstElement[i] + static_cast<cgsize_t>(e));
    if (elements.empty()) continue;
    const std::string name = physicalGroupName(group).substr(0, 32);
    int family = 0, bc = 0;
    check(cg_family_write(z.fn, z.base, name.c_str(), &family), "family");
    // The group's name inside its family too: where the reference's reader looks for the
    // names of physical groups.
    check(cg_family_name_write(z.fn, z.base, family, name.c_str(), name.c_str()), "family name");
    check(cg_boco_write(z.fn, z.base, z.zone, name.c_str(), CGNS_ENUMV(FamilySpecified),
                        CGNS_ENUMV(PointList), static_cast<cgsize_t>(elements.size()),
                        elements.data(), &bc),
          "boundary condition");
    check(cg_boco_gridlocation_write(z.fn, z.base, z.zone, bc, location), "grid location");
    check(cg_goto(z.fn, z.base, "Zone_t", z.zone, "ZoneBC_t", 1, "BC_t", bc, "end"), "goto");
    check(cg_famname_write(name.c_str()), "family name");
  }
}

}  // namespace

// Named by the cgns row of io/formats.cpp, as its path writer: libcgns opens the file itself.
// Saves what an MSH file would; throws std::invalid_argument before creating the file when an
// element cannot be saved.
void writeCgns(const std::string& path, const Model& model, const Mesh& mesh,
               const MeshWriteOptions& options) {
  const MshContent content = selectMshContent(model, mesh, options.saveAll);
  const CgnsPlan plan = planCgns(content);
  CgnsFile file(path);
  CgnsZone z{file.fn(), 0, 0};
  check(cg_base_write(z.fn, "Base", plan.cellDim, 3, &z.base), "base");
  cgsize_t size[3] = {static_cast<cgsize_t>(content.nodeCount),
                      static_cast<cgsize_t>(plan.cellCount), 0};
  check(cg_zone_write(z.fn, z.base, "Zone1", size, CGNS_ENUMV(Unstructured), &z.zone), "zone");
  writeCoordinates(z, mesh, content);
  writeSections(z, content, plan);
  writeBoundaries(z, model, content, plan);
  file.close();
}

// ---- Reading back (io/cgns_summary.h) ----

namespace {

void readCoordinates(int fn, CgnsSummary& s) {
  std::vector<double>* axes[] = {&s.x, &s.y, &s.z};
  const char* names[] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
  cgsize_t first = 1, last = static_cast<cgsize_t>(s.vertices);
  for (int k = 0; k < 3; ++k) {
    axes[k]->resize(static_cast<std::size_t>(s.vertices));
    check(cg_coord_read(fn, 1, 1, names[k], CGNS_ENUMV(RealDouble), &first, &last, axes[k]->data()),
          "coordinates");
  }
}

CgnsSectionSummary readSection(int fn, int section) {
  char name[33];
  CGNS_ENUMT(ElementType_t) type;
  cgsize_t first = 0, last = 0, size = 0;
  int boundaries = 0, parents = 0;
  check(cg_section_read(fn, 1, 1, section, name, &type, &first, &last, &boundaries, &parents),
        "element section");
  check(cg_ElementDataSize(fn, 1, 1, section, &size), "element section size");
  std::vector<cgsize_t> connectivity(static_cast<std::size_t>(size));
  check(cg_elements_read(fn, 1, 1, section, connectivity.data(), nullptr), "elements");
  return {name, cg_ElementTypeName(type), first, last,
          std::vector<long long>(connectivity.begin(), connectivity.end())};
}

CgnsBoundarySummary readBoundary(int fn, int bc) {
  char name[33];
  CGNS_ENUMT(BCType_t) type;
  CGNS_ENUMT(PointSetType_t) pointSet;
  CGNS_ENUMT(DataType_t) normalType;
  CGNS_ENUMT(GridLocation_t) location;
  cgsize_t count = 0, normalSize = 0;
  int normalIndex[3] = {0, 0, 0}, datasets = 0;
  check(cg_boco_info(fn, 1, 1, bc, name, &type, &pointSet, &count, normalIndex, &normalSize,
                     &normalType, &datasets),
        "boundary condition");
  std::vector<cgsize_t> elements(static_cast<std::size_t>(count));
  check(cg_boco_read(fn, 1, 1, bc, elements.data(), nullptr), "boundary condition");
  check(cg_boco_gridlocation_read(fn, 1, 1, bc, &location), "grid location");
  char family[33] = "";
  if (cg_goto(fn, 1, "Zone_t", 1, "ZoneBC_t", 1, "BC_t", bc, "end") == CG_OK)
    cg_famname_read(family);
  return {name, family, cg_GridLocationName(location),
          std::vector<long long>(elements.begin(), elements.end())};
}

}  // namespace

CgnsSummary summarizeCgnsFile(const std::string& path) {
  int fn = -1;
  if (cg_open(path.c_str(), CG_MODE_READ, &fn) != CG_OK)
    throw std::runtime_error("cannot read '" + path + "': " + cg_get_error());
  CgnsSummary s;
  try {
    char base[33], zone[33];
    cgsize_t size[3];
    CGNS_ENUMT(ZoneType_t) zoneType;
    check(cg_base_read(fn, 1, base, &s.cellDim, &s.physicalDim), "base");
    check(cg_zone_read(fn, 1, 1, zone, size), "zone");
    check(cg_zone_type(fn, 1, 1, &zoneType), "zone type");
    s.base = base;
    s.zone = zone;
    s.unstructured = zoneType == CGNS_ENUMV(Unstructured);
    s.vertices = size[0];
    s.cells = size[1];
    readCoordinates(fn, s);
    int sections = 0, boundaries = 0, families = 0;
    check(cg_nsections(fn, 1, 1, &sections), "sections");
    for (int i = 1; i <= sections; ++i) s.sections.push_back(readSection(fn, i));
    check(cg_nbocos(fn, 1, 1, &boundaries), "boundary conditions");
    for (int i = 1; i <= boundaries; ++i) s.boundaries.push_back(readBoundary(fn, i));
    check(cg_nfamilies(fn, 1, &families), "families");
    for (int i = 1; i <= families; ++i) {
      char name[33];
      int bcs = 0, geometries = 0;
      check(cg_family_read(fn, 1, i, name, &bcs, &geometries), "family");
      s.families.push_back(name);
    }
  } catch (const std::runtime_error& error) {
    cg_close(fn);
    throw std::runtime_error("cannot read '" + path + "': " + error.what());
  }
  cg_close(fn);
  return s;
}

}  // namespace geomesh
