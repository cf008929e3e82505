// Pieces shared by the layered sweeps: nodes found by position, and the sweep of a volume.
#pragma once

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/structured/layer_normals.h"

namespace geomesh::extrusion {

// Finds existing nodes by position, within a tolerance, through a hash grid.
class NodeLocator {
 public:
  NodeLocator(const Mesh& mesh, double tolerance)
      : mesh_(mesh), tolerance_(tolerance), cell_(4 * tolerance) {}

  void add(NodeIndex n) { cells_[key(mesh_.node(n))].push_back(n); }

  std::optional<NodeIndex> find(Vec3 p) const {
    const auto [x, y, z] = key(p);
    for (long long i = x - 1; i <= x + 1; ++i)
      for (long long j = y - 1; j <= y + 1; ++j)
        for (long long k = z - 1; k <= z + 1; ++k)
          if (const auto it = cells_.find({i, j, k}); it != cells_.end())
            for (NodeIndex n : it->second)
              if (distance(mesh_.node(n), p) <= tolerance_) return n;
    return std::nullopt;
  }

 private:
  using Key = std::tuple<long long, long long, long long>;
  Key key(Vec3 p) const {
    return {std::llround(p.x / cell_), std::llround(p.y / cell_), std::llround(p.z / cell_)};
  }

  const Mesh& mesh_;
  double tolerance_, cell_;
  std::map<Key, std::vector<NodeIndex>> cells_;
};

// The nodes of the entity's boundary and of their boundaries, down to points.
NodeLocator closureLocator(const Model& model, const Mesh& mesh, EntityId e, double tolerance);

// The normalized heights of the layer boundaries, from 0 to 1: layer i adds elements[i] equal
// steps up to heights[i]. Throws MeshError naming `id` when the layers are malformed.
std::vector<double> layerFractions(const ExtrusionLayers& layers, EntityId id);

std::string nodeText(NodeIndex n);

// What every sweep reads.
struct Sweep {
  const Model& model;
  double tolerance;
  Mesh& mesh;
  const LayerNormals* normals = nullptr;  // for the boundary layers (sweeps along normals)
};

// The layer fractions of the record's sweep (layerFractions); the heights of a boundary layer
// are lengths, taken as fractions of the last one.
std::vector<double> sweepFractions(const ExtrusionRecord& record, EntityId id);

// Where the record's sweep takes p at the layer fraction f: its motion, or for a boundary
// layer, the last height times f along the normal at p.
Vec3 sweptPoint(const Sweep& s, const ExtrusionRecord& record, Vec3 p, double f, EntityId id);

bool isBoundaryLayer(const ExtrusionRecord& record);

// Prisms and hexahedra (Recombine) or tetrahedra over the mesh of the volume's source surface,
// layer by layer; the volume's boundary is meshed.
void meshSweptVolume(const Sweep& s, const ModelVolume& volume);

}  // namespace geomesh::extrusion
