// Writing a session's mesh, geometry and options to files, each through the atomic writer.
#pragma once

#include <string>

#include "api/session.h"
#include "io/formats.h"
#include "stdlib/options.h"

namespace geomesh::api {

// The format a mesh is written in: the one named `formatName` (-format) when given, else the
// one Mesh.Format says (10: the one the extension of `path` names), the MSH version following
// Mesh.MshFileVersion. Throws std::invalid_argument listing the formats of the table when
// none fits.
const MeshFormat& outputFormat(const OptionRegistry& options, const std::string& path,
                               const std::string& formatName = "");

// Mesh.SaveAll, Mesh.Binary and the other options writers read (the size and view of
// pictures: Print.Width, General.RotationX, ...).
MeshWriteOptions writeOptions(const OptionRegistry& options);

// Writes the session's model and mesh to `path`; nothing is left at `path` on failure
// (std::runtime_error naming the file). Without Mesh.SaveAll, warns when physical groups leave
// out meshed entities of a dimension they group, naming them (unsavedEntities); not for
// formats that show every element (pictures).
void writeMesh(const Session& session, const std::string& path, const MeshFormat& format);

// "volume 3, surface 7 (1234 elements)": the meshed entities that no physical group holds
// while groups of their dimension exist, so that a file keeping only physical groups leaves
// them out; "" when there are none.
std::string unsavedEntities(const Model& model, const Mesh& mesh);

// The geometry as a flat script, with its mesh constraints (what -0 and Save
// "f.geo_unrolled" write); OpenCASCADE shapes go to "f.geo_unrolled.xao", which it merges.
void writeUnrolledGeometry(Session& session, const std::string& path);

// The options that differ from their defaults, as a script sets them (Save "f.opt").
void writeChangedOptions(const Session& session, const std::string& path);

}  // namespace geomesh::api
