// The mesh side of (co)homology: the elements a computation runs on, and each resulting
// (co)chain saved as an entity of its own under a physical group.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/homology/cell_complex.h"
#include "mesh/homology/chain_reduction.h"

namespace geomesh {

// The elements (all dimensions) of the entities in the physical groups whose tags are listed,
// whatever the groups' dimensions.
std::vector<ComplexElement> elementsOfGroups(const Model& model, const Mesh& mesh,
                                             std::span<const int> tags);
// The elements of the entities of the highest dimension the mesh has elements of (the whole
// mesh as a domain: points and curves apart from its volumes are left out, as the reference
// does).
std::vector<ComplexElement> highestDimensionElements(const Mesh& mesh);

// Saves a chain of `dim`-cells: a new entity without geometry, tagged after the largest tag of
// any dimension, holds one first-order element per cell, run the cell's way for a positive
// coefficient and the other way for a negative one; a new physical group of dimension `dim`,
// tagged after the largest physical tag, holds the entity. Returns the physical tag.
int addChainGroup(const CellComplex& complex, const Chain& chain, int dim, const std::string& name,
                  Model& model, Mesh& mesh);

}  // namespace geomesh
