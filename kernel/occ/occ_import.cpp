// The OpenCASCADE factory's CAD files: STEP, IGES, BREP and XAO shapes read (scaled, converted
// and healed as the options say), BREP, STEP and XAO written.
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Compound.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <optional>
#include <string>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_healing.h"
#include "kernel/occ/occ_shapes.h"
#include "kernel/occ/occ_xao.h"

namespace geomesh {

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Every root the exchange reader finds in the file, as one shape.
TopoDS_Shape readExchange(XSControl_Reader& reader, const std::string& path, const char* format) {
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw GeometryError("cannot read '" + path + "' as a " + format + " file");
  reader.TransferRoots();
  TopoDS_Shape shape = reader.OneShape();
  if (shape.IsNull()) throw GeometryError("'" + path + "' holds no shape");
  return shape;
}

// Geometry.OCCTargetUnit: the unit OpenCASCADE's STEP and IGES readers convert lengths to
// (millimetres when none is given). Set before every read, so that one read's unit does not
// stick to the next.
void setTargetUnit(const std::string& unit) {
  const std::string name = unit.empty() ? "MM" : unit;
  if (!Interface_Static::SetCVal("xstep.cascade.unit", name.c_str()))
    throw GeometryError("Geometry.OCCTargetUnit: unknown length unit '" + unit +
                        "' (use MM, CM, M, KM, INCH, FT, MI, MIL, UM or UIN)");
}

TopoDS_Shape readShape(const std::string& path, const std::string& targetUnit) {
  std::error_code unreadable;  // a name too long for the system, say: not a file either
  if (!std::filesystem::exists(path, unreadable))
    throw GeometryError("cannot open '" + path + "': no such file");
  const std::string ext = lowerExtension(path);
  if (ext == ".step" || ext == ".stp") {
    STEPControl_Reader reader;
    setTargetUnit(targetUnit);
    return readExchange(reader, path, "STEP");
  }
  if (ext == ".iges" || ext == ".igs") {
    IGESControl_Reader reader;
    setTargetUnit(targetUnit);
    return readExchange(reader, path, "IGES");
  }
  if (ext == ".brep" || ext == ".brp") {
    TopoDS_Shape shape;
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull())
      throw GeometryError("cannot read '" + path + "' as a BREP file");
    return shape;
  }
  if (ext == ".xao") return readXao(path).shape;
  throw GeometryError("'" + path +
                      "': not a STEP (.step, .stp), IGES (.iges, .igs), BREP (.brep) or XAO "
                      "(.xao) file");
}

// Geometry.OCCScaling: the shape scaled about the origin.
TopoDS_Shape scaled(const TopoDS_Shape& shape, double factor) {
  if (factor == 1) return shape;
  if (!(factor > 0) || !std::isfinite(factor))
    throw GeometryError("Geometry.OCCScaling must be a positive number, not " +
                        std::to_string(factor));
  gp_Trsf scale;
  scale.SetScale(gp_Pnt(0, 0, 0), factor);
  return BRepBuilderAPI_Transform(shape, scale, true).Shape();
}

// OpenCASCADE's data exchange reports its progress and its parse errors on standard output;
// geomesh's output is its own (a failed read becomes a GeometryError), so they are silenced.
void quietExchange() {
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
}

// The entities of a geomesh XAO file under their own tags; nullopt (nothing bound) when an
// entity has no tag or its tag is taken.
std::optional<std::vector<EntityId>> bindTagged(OccShapes& shapes, const XaoContents& xao) {
  if (xao.entities.empty()) return std::nullopt;
  for (const XaoEntity& e : xao.entities)
    if (e.tag <= 0 || shapes.contains(e.dim, e.tag) || shapes.isBound(e.dim, e.shape))
      return std::nullopt;
  int top = 0;
  for (const XaoEntity& e : xao.entities) {
    shapes.bindShape(e.dim, e.tag, e.shape);
    top = std::max(top, e.dim);
  }
  bindShapes(shapes, xao.shape, true);  // sub-shapes the file did not list, if any
  std::vector<EntityId> out;
  for (const XaoEntity& e : xao.entities)
    if (e.dim == top) out.push_back({e.dim, e.tag});
  return out;
}

// An XAO file's groups, by the tags their elements got (elements left unbound are dropped).
std::vector<PhysicalGroup> groupsByTag(const OccShapes& shapes,
                                       const std::vector<XaoGroup>& groups) {
  std::vector<PhysicalGroup> out;
  for (const XaoGroup& g : groups) {
    PhysicalGroup group{g.dim, g.tag, g.name, {}};
    for (const TopoDS_Shape& e : g.elements)
      if (shapes.isBound(g.dim, e)) group.entities.push_back(shapes.tagOf(g.dim, e));
    if (group.tag > 0) out.push_back(std::move(group));
  }
  return out;
}

}  // namespace

// The shapes of the highest dimension the file holds get new tags, in the file's order; as in
// the reference, shapes of lower dimensions beside them are not imported (allDimensions: they
// are, after them). An XAO file geomesh wrote gives each entity its tag back, when none of
// them is taken and the shape is neither scaled nor healed.
std::vector<EntityId> OccFactory::importShapes(const std::string& path, bool allDimensions) {
  quietExchange();
  importedGroups_.clear();
  const std::string what = "importing '" + path + "'";
  if (lowerExtension(path) == ".xao" && importOptions_.scaling == 1 &&
      !importOptions_.healing.any()) {
    const XaoContents xao = guarded(what, [&] { return readXao(path); });
    std::optional<std::vector<EntityId>> bound = bindTagged(*shapes_, xao);
    if (!bound) bound = bindShapes(*shapes_, xao.shape, allDimensions);
    importedGroups_ = groupsByTag(*shapes_, xao.groups);
    return *bound;
  }
  const TopoDS_Shape shape = guarded(what, [&] {
    TopoDS_Shape read = scaled(readShape(path, importOptions_.targetUnit), importOptions_.scaling);
    return importOptions_.healing.any() ? healedShape(read, importOptions_.healing) : read;
  });
  return bindShapes(*shapes_, shape, allDimensions);
}

bool OccFactory::hasShapes() const {
  for (int dim = 0; dim <= 3; ++dim)
    if (!shapes_->byTag[dim].empty()) return true;
  return false;
}

// Save "x.brep" / "x.step": the entities not part of others, as one compound.
void OccFactory::exportShapes(const std::string& path) const {
  const TopoDS_Shape all = compoundOfAll(*shapes_);
  const std::string ext = lowerExtension(path);
  quietExchange();
  guarded("writing '" + path + "'", [&] {
    if (ext == ".xao") {
      writeXao(*shapes_, all, path);
    } else if (ext == ".brep" || ext == ".brp") {
      if (!BRepTools::Write(all, path.c_str())) throw GeometryError("cannot write '" + path + "'");
    } else if (ext == ".step" || ext == ".stp") {
      STEPControl_Writer writer;
      if (writer.Transfer(all, STEPControl_AsIs) != IFSelect_RetDone ||
          writer.Write(path.c_str()) != IFSelect_RetDone)
        throw GeometryError("cannot write '" + path + "'");
    } else {
      throw GeometryError("'" + path +
                          "': the OpenCASCADE factory writes .brep, .step and .xao files");
    }
    return 0;
  });
}

}  // namespace geomesh
