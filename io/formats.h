// The mesh file formats, one row each: every choice of a format (by -format name, file
// extension or Mesh.Format code) goes through this table.
#pragma once

#include <array>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// What every writer is told; a format ignores what it cannot express.
struct MeshWriteOptions {
  bool saveAll = false;  // Mesh.SaveAll: also save elements outside physical groups
  bool binary = false;   // Mesh.Binary, for formats with a binary form
  // Mesh.SaveGroupsOfElements and Mesh.SaveGroupsOfNodes, for formats that hold named sets
  // (UNV, INP, ...): 0 none; 1 every physical group; negative -d...: digit k+1 (from the
  // right) of its opposite, when 1, selects the groups of dimension k.
  int saveGroupsOfElements = 1;
  int saveGroupsOfNodes = 0;
  // Partitioned meshes in MSH files: Mesh.PartitionOldStyleMsh2, and
  // Mesh.PartitionSplitMeshFiles (one file per partition, "name_1.msh", "name_2.msh", ...).
  bool partitionOldStyleMsh2 = true;
  bool splitPartitions = false;
  int onlyPartition = 0;  // > 0: that partition only (set when splitting)
  // Pictures (SVG, PNG): the size in pixels (Print.Width and Print.Height when set, else
  // General.GraphicsWidth and General.GraphicsHeight) and the view's Euler angles in degrees
  // (General.RotationX, Y, Z), unset when all three are 0 (their default): then a planar mesh
  // is seen from +z and any other from an oblique direction.
  int pictureWidth = 800;
  int pictureHeight = 600;
  std::optional<std::array<double, 3>> viewRotation = std::nullopt;
};

// Whether a physical group of dimension `dim` is saved as a set under a SaveGroupsOf* value.
bool savesGroupsOfDimension(int saveGroups, int dim);

using MeshWriter = void (*)(std::ostream& out, const Model& model, const Mesh& mesh,
                            const MeshWriteOptions& options);
// Replaces `model` and `mesh` by the file's content; `name` prefixes error messages.
using MeshReader = void (*)(std::istream& in, Model& model, Mesh& mesh, const std::string& name);
// For formats whose library opens the file itself (CGNS): writes a complete file at `path`.
using MeshFileWriter = void (*)(const std::string& path, const Model& model, const Mesh& mesh,
                                const MeshWriteOptions& options);
// For formats whose library opens the file itself (CGNS): replaces `model` and `mesh` by the
// content of the file at `path`.
using MeshFileReader = void (*)(const std::string& path, Model& model, Mesh& mesh);

struct MeshFormat {
  std::string_view names;       // accepted by -format, space-separated; the first is its name
  std::string_view extensions;  // space-separated, with the dot (".msh")
  int code = 0;                 // Mesh.Format; 0 for formats the Gmsh manual gives no code
  // Rows that share an extension or a code are versions of one format: the row chosen is the
  // first whose minVersion is at most the version asked for (Mesh.MshFileVersion).
  double minVersion = 0;
  MeshWriter write = nullptr;  // null when the format is only read
  MeshReader read = nullptr;   // null when the format is only written
  int maxOrder = 1;            // the highest element order the format holds
  // Set instead of `write` for a format written by a library to a path: writeMeshFile gives it
  // a temporary path, renamed once the file is complete.
  MeshFileWriter writeFile = nullptr;
  // Set instead of `read` for a format read by a library from a path.
  MeshFileReader readFile = nullptr;
  // Whether the format holds partitions, so that Mesh.PartitionSplitMeshFiles writes one file
  // per partition (MeshWriteOptions::onlyPartition) instead of one file.
  bool holdsPartitions = false;
  // Whether the format shows every element whatever the physical groups (pictures), so that
  // Mesh.SaveAll changes nothing for it.
  bool showsAllElements = false;

  bool writes() const { return write || writeFile; }
  bool reads() const { return read || readFile; }

  std::string_view name() const { return names.substr(0, names.find(' ')); }
  bool isNamed(std::string_view name) const;
  bool hasExtension(std::string_view extension) const;
};

std::span<const MeshFormat> meshFormats();

// Why `format` cannot hold elements of order `order` ("vtk files hold elements up to order
// 2"), or "" when it can: asked before meshing, so that a run does not fail at its end.
std::string orderUnsupportedReason(const MeshFormat& format, int order);

// Null when no row matches. `version` chooses among the rows sharing an extension or a code.
const MeshFormat* findFormatByName(std::string_view name);
const MeshFormat* findFormatByExtension(std::string_view extension, double version);
const MeshFormat* findFormatByCode(int code, double version);
// The first format read from files with that extension.
const MeshFormat* findReaderByExtension(std::string_view extension);

// For messages and help: "msh41, msh4, msh, msh22, msh2"; "msh41 (msh4, msh), msh22 (msh2)";
// the extensions written (".msh") or read, each once; the codes written ("1 (msh)").
std::string formatNameList();
std::string formatNameGroups();
std::string writtenExtensionList();
std::string readExtensionList();
std::string formatCodeList();

// Writes through writeFileAtomically; throws std::runtime_error naming `path`.
void writeMeshFile(const std::string& path, const MeshFormat& format, const Model& model,
                   const Mesh& mesh, const MeshWriteOptions& options);
// Reads with the format's reader (or path reader); throws std::runtime_error when the file
// cannot be opened, and the reader's error (MshReadError for MSH) when its content is malformed.
void readMeshFile(const std::string& path, const MeshFormat& format, Model& model, Mesh& mesh);

}  // namespace geomesh
