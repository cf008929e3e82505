// Reading BREP, STEP and IGES files into the OpenCASCADE factory (Merge, ShapeFromFile).
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"

namespace geomesh {
namespace {

std::string lowercaseExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// OpenCASCADE's readers report their progress on standard output, where geomesh writes what
// scripts print: while one reads, its printers pass failures only.
class QuietReading {
 public:
  QuietReading() {
    const Message_SequenceOfPrinters& printers = Message::DefaultMessenger()->Printers();
    for (Message_SequenceOfPrinters::Iterator it(printers); it.More(); it.Next()) {
      saved_.emplace_back(it.Value(), it.Value()->GetTraceLevel());
      it.Value()->SetTraceLevel(Message_Fail);
    }
  }
  ~QuietReading() {
    for (auto& [printer, level] : saved_) printer->SetTraceLevel(level);
  }
  QuietReading(const QuietReading&) = delete;
  QuietReading& operator=(const QuietReading&) = delete;

 private:
  std::vector<std::pair<Handle(Message_Printer), Message_Gravity>> saved_;
};

// STEP and IGES readers share their interface: read, transfer every root, one shape.
template <typename Reader>
TopoDS_Shape readExchangeFile(const std::string& path, const char* format) {
  const QuietReading quiet;
  Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw GeometryError("cannot read '" + path + "' as a " + format + " file");
  if (reader.TransferRoots() == 0)
    throw GeometryError("'" + path + "' holds no shape that can be transferred");
  return reader.OneShape();
}

TopoDS_Shape readBrep(const std::string& path) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  if (!BRepTools::Read(shape, path.c_str(), builder))
    throw GeometryError("cannot read '" + path + "' as a BREP file");
  return shape;
}

TopoDS_Shape readShapeFile(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw GeometryError("cannot open '" + path + "': no such file");
  const std::string ext = lowercaseExtension(path);
  if (ext == ".brep" || ext == ".brp") return readBrep(path);
  if (ext == ".step" || ext == ".stp") return readExchangeFile<STEPControl_Reader>(path, "STEP");
  if (ext == ".iges" || ext == ".igs") return readExchangeFile<IGESControl_Reader>(path, "IGES");
  throw GeometryError("cannot import '" + path + "': not a BREP, STEP or IGES file");
}

}  // namespace

std::vector<EntityId> OccFactory::importShapes(const std::string& path) {
  try {
    const TopoDS_Shape shape = readShapeFile(path);
    if (shape.IsNull()) throw GeometryError("'" + path + "' holds no shape");
    return bindTopLevel(shape);
  } catch (const Standard_Failure& e) {
    throw GeometryError("cannot import '" + path + "': " + e.GetMessageString());
  }
}

}  // namespace geomesh
