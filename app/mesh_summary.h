// MeshSummary: the figures of a run that golden tests compare, and the model's description.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// What a run produced, in the figures golden tests compare: element counts per type,
// measures per dimension, quality, and the physical groups.
struct MeshSummary {
  std::size_t nodes = 0;
  std::map<ElementType, std::size_t> elements;
  double length = 0;  // total length of the 1D elements
  double area = 0;    // total area of the 2D elements
  double volume = 0;  // total volume of the 3D elements
  // Gamma of the highest-dimensional elements (1 for an equilateral one); 0 when none.
  double minQuality = 0;
  double meanQuality = 0;
  // Validity of curved meshes, measured when any element has order 2 or more: the minimum
  // scaled Jacobian over all elements (of dimension 1 to 3) and how many are <= 0.
  bool highOrder = false;
  double minScaledJacobian = 0;
  std::size_t invalidElements = 0;
  // Boundary layers: the elements of the entities grown along normals (Extrude without a
  // vector) and of the layers that BoundaryLayer fields build in surfaces, with the smallest
  // and mean scaled Jacobian at their corners (cornerScaledJacobian).
  std::size_t layerElements = 0;
  double layerMinJacobian = 0;
  double layerMeanJacobian = 0;
  // Meshes with quadrangles: the vertices of quadrangles only that are off the boundary of
  // the surface elements (edges of one element only), and those with other than four edges.
  std::size_t interiorVertices = 0;
  std::size_t irregularVertices = 0;
  // Meshes with hexahedra: the volume of the hexahedra (their share of `volume`).
  double hexahedraVolume = 0;
  struct Group {
    int dim = 0;
    int tag = 0;
    std::string name;
    std::size_t elements = 0;
  };
  std::vector<Group> physicalGroups;
};

MeshSummary summarizeMesh(const Model& model, const Mesh& mesh);
std::string formatSummary(const MeshSummary& summary);
// "curved elements: scaled Jacobian min 0.62, 0 invalid"; empty when not highOrder.
std::string formatCurvedValidity(const MeshSummary& summary);
// "boundary layer: 340 elements, scaled Jacobian min 0.81, mean 0.97"; empty without one.
std::string formatLayerQuality(const MeshSummary& summary);
// "quadrangles: 12 of 410 interior vertices irregular (not 4 edges)"; empty without quadrangles.
std::string formatQuadStructure(const MeshSummary& summary);
// "hexahedra: 72.5% of the volume"; empty without hexahedra.
std::string formatHexShare(const MeshSummary& summary);
// "4 points, 4 curves, 1 surface, 0 volumes, 2 physical groups"
std::string describeModel(const Model& model);

}  // namespace geomesh
