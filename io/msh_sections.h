// The MSH sections shared by the writers of each version: header, names, bodies, $Periodic.
#pragma once

#include "io/msh_content.h"
#include "io/msh_encoder.h"
#include "io/msh_writer.h"
#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// The sections of MSH files, shared by the writers of each version.
void writeMeshFormat(MshEncoder& out, const char* version);
// Binary data is followed by a line break before the end marker.
void endSection(MshEncoder& out, const char* endMarker);
// Only when some have names; with the groups made per partition when there are some.
void writePhysicalNames(MshEncoder& out, const Model& model, const MeshPartitions* partitions);

void writeMsh41Body(MshEncoder& out, const Model& model, const Mesh& mesh,
                    const MshContent& content);
void writeMsh22Body(MshEncoder& out, const Model& model, const Mesh& mesh,
                    const MshContent& content, const MshWriteOptions& options);
// $Periodic, when some saved entity is periodic; `msh2` selects the MSH 2.2 layout.
void writePeriodic(MshEncoder& out, const Mesh& mesh, const MshContent& content, bool msh2);

}  // namespace geomesh
