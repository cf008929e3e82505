// touchingVolumes: volumes that meet without sharing the surfaces between them.
#pragma once

#include <string>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Pairs of volumes whose boundaries have surfaces at the same place without sharing them (two
// copies of a face, as a script that forgets Coherence or BooleanFragments makes): their
// meshes are not connected there. Found from the surface meshes: a triangle of a surface
// bounding one volume with its corners exactly at those of a triangle of a surface bounding
// another (copies meshed alike, as copies of a face are; copies meshed differently are not
// found). One message per pair of surfaces, naming both volumes, both surfaces and a point.
std::vector<std::string> touchingVolumes(const Model& model, const Mesh& mesh);

}  // namespace geomesh
