// The OpenCASCADE factory's CAD files: STEP, IGES and BREP shapes read, BREP and STEP written.
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
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
#include <filesystem>
#include <set>
#include <string>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

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

TopoDS_Shape readShape(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw GeometryError("cannot open '" + path + "': no such file");
  const std::string ext = lowerExtension(path);
  if (ext == ".step" || ext == ".stp") {
    STEPControl_Reader reader;
    return readExchange(reader, path, "STEP");
  }
  if (ext == ".iges" || ext == ".igs") {
    IGESControl_Reader reader;
    return readExchange(reader, path, "IGES");
  }
  if (ext == ".brep" || ext == ".brp") {
    TopoDS_Shape shape;
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull())
      throw GeometryError("cannot read '" + path + "' as a BREP file");
    return shape;
  }
  throw GeometryError("'" + path +
                      "': not a STEP (.step, .stp), IGES (.iges, .igs) or BREP (.brep) file");
}

// OpenCASCADE's data exchange reports its progress and its parse errors on standard output;
// geomesh's output is its own (a failed read becomes a GeometryError), so they are silenced.
void quietExchange() {
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
}

constexpr TopAbs_ShapeEnum kTypes[4] = {TopAbs_VERTEX, TopAbs_EDGE, TopAbs_FACE, TopAbs_SOLID};

}  // namespace

// The shapes of the highest dimension the file holds get new tags, in the file's order; as in
// the reference, shapes of lower dimensions beside them are not imported.
std::vector<EntityId> OccFactory::importShapes(const std::string& path) {
  quietExchange();
  const TopoDS_Shape shape = guarded("importing '" + path + "'", [&] { return readShape(path); });
  std::vector<EntityId> out;
  std::set<EntityId> listed;
  for (int dim = 3; dim >= 0; --dim) {
    TopExp_Explorer it = dim == 3 ? TopExp_Explorer(shape, kTypes[3])
                                  : TopExp_Explorer(shape, kTypes[dim], kTypes[dim + 1]);
    for (; it.More(); it.Next()) {
      const EntityId e{dim, shapes_->bindNew(dim, it.Current())};
      if (listed.insert(e).second) out.push_back(e);
    }
    if (!out.empty()) break;
  }
  return out;
}

// Save "x.brep" / "x.step": the entities not part of others, as one compound.
void OccFactory::exportShapes(const std::string& path) const {
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  TopTools_IndexedMapOfShape inside;
  for (int dim = 3; dim >= 0; --dim)
    for (const auto& [tag, shape] : shapes_->byTag[dim]) {
      if (inside.Contains(shape)) continue;
      builder.Add(all, shape);
      for (int sub = dim - 1; sub >= 0; --sub) TopExp::MapShapes(shape, kTypes[sub], inside);
    }
  const std::string ext = lowerExtension(path);
  quietExchange();
  guarded("writing '" + path + "'", [&] {
    if (ext == ".brep" || ext == ".brp") {
      if (!BRepTools::Write(all, path.c_str())) throw GeometryError("cannot write '" + path + "'");
    } else if (ext == ".step" || ext == ".stp") {
      STEPControl_Writer writer;
      if (writer.Transfer(all, STEPControl_AsIs) != IFSelect_RetDone ||
          writer.Write(path.c_str()) != IFSelect_RetDone)
        throw GeometryError("cannot write '" + path + "'");
    } else {
      throw GeometryError("'" + path + "': the OpenCASCADE factory writes .brep and .step files");
    }
    return 0;
  });
}

}  // namespace geomesh
