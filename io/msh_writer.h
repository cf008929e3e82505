// writeMsh and MshWriteOptions: a mesh in Gmsh's MSH format, 4.1 or 2.2, ASCII or binary.
#pragma once

#include <iosfwd>
#include <string>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

struct MshWriteOptions {
  bool saveAll = false;  // Mesh.SaveAll: also save elements outside physical groups
  bool binary = false;   // Mesh.Binary
  double version = 4.1;  // Mesh.MshFileVersion: 4.1 or 2.2
  // Partitioned meshes: Mesh.PartitionOldStyleMsh2 (MSH 2.2 elements carry the tag of the
  // model entity, not of the piece); a partition number > 0 saves that partition only.
  bool partitionOldStyle = true;
  int onlyPartition = 0;
};

// Writes the mesh in Gmsh's MSH format. When the model has physical groups and saveAll is
// off, only the elements of entities in physical groups are written, with the nodes they use.
// Nodes and elements are numbered consecutively from 1, entity by entity in (dim, tag) order.
// Throws std::invalid_argument for an unsupported version or an inconsistent mesh.
void writeMsh(std::ostream& out, const Model& model, const Mesh& mesh,
              const MshWriteOptions& options);

// Writes to `path` through writeFileAtomically: a failure (thrown as std::runtime_error
// naming the file) never leaves a partial file behind.
void writeMshFile(const std::string& path, const Model& model, const Mesh& mesh,
                  const MshWriteOptions& options);

}  // namespace geomesh
