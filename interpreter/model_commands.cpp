// Statements that act on the whole model or its mesh while the script runs: Mesh n; Save and
// Print "file"; Merge "file"; Delete Model / All / Variables / Options / <name>; NewModel;
// SyncModel.
#include <algorithm>
#include <array>
#include <filesystem>

#include "api/meshing.h"
#include "api/output.h"
#include "api/partitioning.h"
#include "api/session.h"
#include "interpreter/diagnostics.h"
#include "interpreter/script_interpreter.h"
#include "mesh/high_order/set_order.h"

namespace geomesh {

namespace {

std::string extensionOf(const std::filesystem::path& path) {
  return path.extension().string();
}

// Mesh 2; Save "file"; Merge "file"; Delete name; take one bare argument.
bool hasBareArgument(const ast::CommandStmt& command) {
  return command.argStyle == ast::CommandStmt::Args::Bare && command.args.size() == 1;
}

}  // namespace

void Interpreter::executeMesh(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!hasBareArgument(command)) return unsupportedStatement(command, where);
  meshNow(*command.args[0], where);
}

// SetOrder n; gives the mesh made so far the order n (1 to 4), as Mesh.ElementOrder would.
void Interpreter::executeSetOrder(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!hasBareArgument(command)) return unsupportedStatement(command, where);
  const double n = evaluateNumber(*command.args[0]);
  const int order = clampedInteger<int>(n);
  if (n != order) fail(command.args[0]->loc, "'SetOrder' takes a whole number");
  if (const std::string why = unsupportedOrderReason(order); !why.empty())
    fail(command.args[0]->loc, why);
  if (session_.sandboxed()) {
    warn(where, "'SetOrder' skipped: this session meshes nothing");
    return;
  }
  try {
    api::setOrder(session_, order);
  } catch (const ScriptError& error) {
    fail(error.location(), error.message());
  } catch (const std::runtime_error& error) {
    fail(where, error.what());
  }
}

// PartitionMesh n; splits the current mesh with METIS, as -part n does after meshing.
void Interpreter::executePartitionMesh(const ast::CommandStmt& command,
                                       const SourceLocation& where) {
  if (!hasBareArgument(command)) return unsupportedStatement(command, where);
  const double n = evaluateNumber(*command.args[0]);
  const int count = clampedInteger<int>(n);
  if (n != count || count < 1)
    fail(command.args[0]->loc, "'PartitionMesh' takes a whole number of partitions, at least 1");
  if (session_.sandboxed()) {
    warn(where, "'PartitionMesh' skipped: this session meshes nothing");
    return;
  }
  // As in the reference, the count becomes Mesh.NbPartitions: meshing again partitions again.
  session_.options().setNumber("Mesh.NbPartitions", count);
  try {
    api::partitionMesh(session_, count);
  } catch (const std::exception& error) {
    fail(where, error.what());
  }
}

void Interpreter::executeSave(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!hasBareArgument(command)) return unsupportedStatement(command, where);
  saveFile(command, where);
}

// Print "file"; saves as Save does; Print's other forms drive the graphical interface.
void Interpreter::executePrint(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!hasBareArgument(command)) return skipInBatch(command, where);
  saveFile(command, where);
}

void Interpreter::executeMerge(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!hasBareArgument(command)) return unsupportedStatement(command, where);
  mergeFile(command, where);
}

void Interpreter::executeNewModel(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!command.args.empty()) return unsupportedStatement(command, where);
  startNewModel();
}

// SyncModel; the built-in kernel's entities reach the model before every use: nothing is left
// to do. RenumberMeshNodes; RenumberMeshElements; written meshes are always numbered
// consecutively from 1: nothing to renumber.
void Interpreter::executeAlreadyDone(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!command.args.empty()) unsupportedStatement(command, where);
}

void Interpreter::executeCoherenceMesh(const ast::CommandStmt& command,
                                       const SourceLocation& where) {
  if (!command.args.empty()) return unsupportedStatement(command, where);
  // A generated mesh shares the nodes of common boundaries: there are no duplicates to
  // merge. A mesh read from a file keeps whatever it holds.
  if (session_.meshFromFile())
    warn(where, "'Coherence Mesh' on a mesh read from a file is not supported yet; ignored");
}

// Delete Model; Delete name; and Delete { shapes }.
void Interpreter::executeDelete(const ast::CommandStmt& command, const SourceLocation& where) {
  if (hasBareArgument(command) && !command.shape) {
    if (!deleteByName(*command.args[0], where)) unsupportedStatement(command, where);
    return;
  }
  deleteShapes(command, where);
}

// Synchronizes the model, reporting at `where` what prevents it.
void Interpreter::synchronizeModel(const SourceLocation& where) {
  try {
    session_.synchronize();
  } catch (const std::runtime_error& error) {
    fail(where, error.what());
  }
}

void Interpreter::startNewModel() {
  session_.clearModel();
  deletedPhysicalTag_ = 0;
}

// Mesh n; meshes the model as it stands, up to dimension n, with the options set so far.
void Interpreter::meshNow(const ast::Expr& dimension, const SourceLocation& where) {
  const double dim = evaluateNumber(dimension);
  if (dim != 0 && dim != 1 && dim != 2 && dim != 3)
    fail(dimension.loc, "'Mesh' takes a dimension 0, 1, 2 or 3");
  if (session_.sandboxed()) {
    warn(where, "'Mesh' skipped: this session meshes nothing");
    return;
  }
  try {
    api::generate(session_, clampedInteger<int>(dim));
  } catch (const ScriptError& error) {
    // The statement that defined the entity, quoted from the script text as it was run.
    fail(error.location(), error.message());
  } catch (const std::runtime_error& error) {
    fail(where, error.what());
  }
}

// Save "file"; (and Print, which Gmsh treats alike) writes the mesh (in the format of
// io/formats.h its extension names), the changed options or the unrolled geometry, relative
// to the script's directory.
void Interpreter::saveFile(const ast::CommandStmt& command, const SourceLocation& where) {
  const ast::Expr& name = *command.args[0];
  std::filesystem::path path = evaluateString(name);
  if (path.is_relative()) path = std::filesystem::path(directoryOf(where.file)) / path;
  const std::string ext = extensionOf(path);
  const std::string shown = path.lexically_normal().string();
  if (session_.sandboxed()) {
    warn(where,
         "'" + command.words[0] + "' of '" + shown + "' skipped: this session writes no file");
    return;
  }
  if (ext == ".brep" || ext == ".step" || ext == ".stp" || ext == ".xao")
    return saveCadFile(shown, where);
  const MeshFormat* format =
      findFormatByExtension(ext, session_.options().number("Mesh.MshFileVersion"));
  if (!format && ext != ".opt" && ext != ".geo_unrolled") {
    warn(where, "'" + command.words[0] + "' cannot write '" + shown + "': this format is not " +
                    "supported yet (only " + writtenExtensionList() +
                    ", .opt and .geo_unrolled); ignored");
    return;
  }
  // Nothing meshed yet: a mesh file still lists the entities, as Gmsh's does.
  if (format && session_.mesh().nodeCount() == 0) synchronizeModel(where);
  try {
    if (format)
      api::writeMesh(session_, path.string(), *format);
    else if (ext == ".opt")
      api::writeChangedOptions(session_, path.string());
    else
      api::writeUnrolledGeometry(session_, path.string());
  } catch (const std::runtime_error& error) {
    fail(name.loc, error.what());
  }
  session_.log().info("Wrote '" + shown + "'");
}

// Merge "file.geo"; reads the script as Include does (so do .opt and .geo_unrolled files,
// which are scripts too). Merge "file.msh"; reads a mesh (any format of io/formats.h with a
// reader), as long as the script has no geometry of its own; other files are not merged.
void Interpreter::mergeFile(const ast::CommandStmt& command, const SourceLocation& where) {
  const ast::Expr& name = *command.args[0];
  const std::string file = evaluateString(name);
  const std::string ext = extensionOf(file);
  if (ext == ".geo" || ext == ".opt" || ext == ".geo_unrolled")
    return executeInclude(command, where);
  if (ext == ".pos" || ext == ".bgm") return mergeViewFile(command, where);
  if (ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs" || ext == ".brep" ||
      ext == ".brp" || ext == ".xao")
    return mergeCadFile(file, where);
  if (!findReaderByExtension(ext)) {
    session_.noteIgnoredStatement(where);
    warn(where, "'Merge' of '" + file + "' is not supported yet (only .geo, .opt, " +
                    ".geo_unrolled, .pos and " + readExtensionList() + "); ignored");
    return;
  }
  std::filesystem::path path = file;
  if (path.is_relative()) path = std::filesystem::path(directoryOf(where.file)) / path;
  const std::string shown = path.lexically_normal().string();
  if (session_.hasGeometry() || session_.meshFromFile() || session_.mesh().nodeCount() > 0) {
    if (ext == ".msh" && mergeDataOnly(shown, where)) return;
    warn(where, "'Merge' of '" + file + "' into a model that already has " +
                    (session_.meshFromFile() ? "a mesh file" : "geometry") +
                    " is not supported yet; ignored");
    return;
  }
  try {
    session_.readMesh(shown);
  } catch (const std::runtime_error& error) {
    fail(name.loc, error.what());
  }
  if (ext == ".msh") readViewsOfMesh(shown, where);
  session_.log().info("Merged '" + shown + "': " + std::to_string(session_.mesh().nodeCount()) +
                      " nodes");
}

// Delete Model; Delete All; Delete Variables; Delete Options; Delete name;
bool Interpreter::deleteByName(const ast::Expr& what, const SourceLocation& where) {
  if (what.kind != ast::ExprKind::Variable) return false;
  const std::string name = resolveName(what.name);
  if (what.name.suffixes.empty() && (name == "Model" || name == "All")) {
    startNewModel();
    return true;
  }
  if (what.name.suffixes.empty() && name == "Variables") {
    variables_.clear();
    return true;
  }
  if (what.name.suffixes.empty() && name == "Options") {
    // Back to the defaults, except how much the user asked to see.
    const double verbosity = session_.options().number("General.Verbosity");
    session_.options().reset();
    session_.options().setNumber("General.Verbosity", verbosity);
    optionChanged("Geometry.Tolerance");
    return true;
  }
  if (variables_.erase(name) == 0)
    warn(where, "'Delete " + name + "': no variable '" + name + "' to delete; ignored");
  return true;
}

// Read-only options describing the model and its mesh, computed when a script reads them:
// General.MinX ... General.MaxZ and General.BoundingBoxSize, Mesh.NbNodes, Mesh.NbTriangles,
// ... Null for any other option.
std::optional<double> Interpreter::modelStatistic(std::string_view name) {
  static constexpr std::pair<std::string_view, std::array<ElementType, 3>> kFamilies[] = {
      {"Mesh.NbTriangles",
       {ElementType::Triangle3, ElementType::Triangle6, ElementType::Triangle6}},
      {"Mesh.NbQuadrangles", {ElementType::Quad4, ElementType::Quad8, ElementType::Quad9}},
      {"Mesh.NbTetrahedra", {ElementType::Tet4, ElementType::Tet10, ElementType::Tet10}},
      {"Mesh.NbHexahedra", {ElementType::Hex8, ElementType::Hex20, ElementType::Hex27}},
      {"Mesh.NbPrisms", {ElementType::Prism6, ElementType::Prism15, ElementType::Prism18}},
      {"Mesh.NbPyramids", {ElementType::Pyramid5, ElementType::Pyramid13, ElementType::Pyramid14}},
  };
  const Mesh& mesh = session_.mesh();
  if (name == "Mesh.NbNodes") return static_cast<double>(mesh.nodeCount());
  for (const auto& [option, types] : kFamilies) {
    if (name != option) continue;
    double count = 0;
    for (const auto& [entity, part] : mesh.entities())
      for (const auto& block : part.blocks)
        if (std::find(types.begin(), types.end(), block.type) != types.end())
          count += static_cast<double>(block.size());
    return count;
  }
  constexpr std::string_view kBounds[] = {"General.MinX",           "General.MinY", "General.MinZ",
                                          "General.MaxX",           "General.MaxY", "General.MaxZ",
                                          "General.BoundingBoxSize"};
  const auto found = std::find(std::begin(kBounds), std::end(kBounds), name);
  if (found == std::end(kBounds)) return std::nullopt;
  const auto which = static_cast<std::size_t>(found - std::begin(kBounds));
  try {
    session_.synchronize();
  } catch (const std::runtime_error&) {
    return std::nullopt;  // no valid model yet: the option keeps its value
  }
  const BoundingBox box = session_.model().boundingBox();
  if (box.empty()) return std::nullopt;
  const double corner[] = {box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z};
  if (which < 6) return corner[which];
  return distance(box.min, box.max);
}

}  // namespace geomesh
