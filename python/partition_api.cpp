// Partitions from Python: geomesh.model.mesh.partition / unpartition, and the model queries that
// see the partition entities (getPartitions, getParent, getNumberOfPartitions, getType), as
// PartitionMesh n; and the partitioned mesh file give them.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/partitioning.h"
#include "kernel/geometry.h"
#include "kernel/model.h"
#include "python/api_state.h"

namespace py = pybind11;

namespace geomesh::python {
namespace {

const PartitionEntity* partitionEntity(const Mesh& mesh, int dim, int tag) {
  if (const MeshPartitions* partitions = mesh.partitions())
    for (const PartitionEntity& piece : partitions->entities)
      if (piece.id == EntityId{dim, tag}) return &piece;
  return nullptr;
}

const char* curveType(CurveKind kind) {
  switch (kind) {
    case CurveKind::Line: return "Line";
    case CurveKind::CircleArc: return "Circle";
    case CurveKind::EllipseArc: return "Ellipse";
    case CurveKind::Spline: return "Spline";
    case CurveKind::BSpline: return "BSpline";
    case CurveKind::Bezier: return "Bezier";
    case CurveKind::Other: break;
  }
  return "Unknown";
}

const char* surfaceType(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::Plane: return "Plane";
    case SurfaceKind::Cylinder: return "Cylinder";
    case SurfaceKind::Cone: return "Cone";
    case SurfaceKind::Sphere: return "Sphere";
    case SurfaceKind::Torus: return "Torus";
    case SurfaceKind::BSpline: return "BSpline surface";
    case SurfaceKind::Bezier: return "Bezier surface";
    case SurfaceKind::Other: break;
  }
  return "Surface";
}

// The reference's names of entity types: "Point", "Line", "Plane", "Volume", "Discrete
// surface", "Partition curve", ...
std::string entityType(const Session& session, int dim, int tag) {
  static const char* const kDimension[] = {"point", "curve", "surface", "volume"};
  if (partitionEntity(session.mesh(), dim, tag)) return std::string("Partition ") + kDimension[dim];
  const Model& model = session.model();
  if (!model.contains({dim, tag}))
    raiseError("Error", "no entity (" + std::to_string(dim) + ", " + std::to_string(tag) + ")");
  switch (dim) {
    case 0:
      return model.point(tag)->discrete ? "Discrete point" : "Point";
    case 1: {
      const ModelCurve& curve = *model.curve(tag);
      if (curve.discrete || !curve.geometry) return "Discrete curve";
      return curveType(curve.geometry->kind());
    }
    case 2: {
      const ModelSurface& surface = *model.surface(tag);
      if (surface.discrete || !surface.geometry) return "Discrete surface";
      return surfaceType(surface.geometry->kind());
    }
    default:
      return "Volume";
  }
}

}  // namespace

void definePartitions(py::module_& model, py::module_& mesh, const State& state) {
  mesh.def(
      "partition",
      [state](int numPart, const std::vector<std::size_t>& elementTags,
              const std::vector<int>& partitions) {
        if (numPart < 1)
          throw py::value_error("numPart must be at least 1, got " + std::to_string(numPart));
        if (!elementTags.empty() || !partitions.empty())
          throw py::value_error(
              "elementTags and partitions: partitions chosen per element are not supported; "
              "give numPart only (METIS chooses them)");
        state->meshWillChange();
        try {
          api::partitionMesh(state->session(), numPart);
        } catch (const std::invalid_argument& e) {
          raiseError("MeshError", e.what());
        }
      },
      py::arg("numPart"), py::arg("elementTags") = std::vector<std::size_t>{},
      py::arg("partitions") = std::vector<int>{},
      "Splits the mesh into numPart partitions with METIS (Mesh.Partition* and Mesh.Metis* "
      "options apply), as PartitionMesh numPart; does.");
  mesh.def(
      "unpartition",
      [state] {
        state->meshWillChange();
        state->session().mesh().clearPartitions();
      },
      "Drops the partitions: the mesh is the entities' again.");

  model.def(
      "getNumberOfPartitions",
      [state] {
        const MeshPartitions* p = state->session().mesh().partitions();
        return p ? p->count : 0;
      },
      "The number of partitions of the mesh (0 when it is not partitioned).");
  model.def(
      "getPartitions",
      [state](int dim, int tag) {
        const PartitionEntity* piece = partitionEntity(state->session().mesh(), dim, tag);
        return piece ? piece->partitions : std::vector<int>{};
      },
      py::arg("dim"), py::arg("tag"),
      "The partitions a partition entity belongs to; [] for the model's own entities.");
  model.def(
      "getParent",
      [state](int dim, int tag) {
        const PartitionEntity* piece = partitionEntity(state->session().mesh(), dim, tag);
        const EntityId parent = piece ? piece->parent : EntityId{-1, -1};
        return py::make_tuple(parent.dim, parent.tag);
      },
      py::arg("dim"), py::arg("tag"),
      "The model entity (dim, tag) a partition entity is a piece of; (-1, -1) for others.");
  model.def(
      "getType", [state](int dim, int tag) { return entityType(state->session(), dim, tag); },
      py::arg("dim"), py::arg("tag"),
      "The type of an entity: \"Point\", \"Line\", \"Circle\", \"Plane\", \"BSpline surface\", "
      "\"Volume\", \"Discrete surface\", \"Partition curve\", ...");
}

// The partition entities of dimension `dim` (-1: all), after the model's own.
std::vector<EntityId> partitionEntityIds(const Session& session, int dim) {
  std::vector<EntityId> ids;
  if (const MeshPartitions* partitions = session.mesh().partitions())
    for (const PartitionEntity& piece : partitions->entities)
      if (dim < 0 || piece.id.dim == dim) ids.push_back(piece.id);
  return ids;
}

// The boundary of a partition entity, or null for the model's entities.
std::optional<std::vector<EntityId>> partitionBoundary(const Session& session, EntityId id,
                                                       bool oriented) {
  const PartitionEntity* piece = partitionEntity(session.mesh(), id.dim, id.tag);
  if (!piece) return std::nullopt;
  std::vector<EntityId> result;
  for (int tag : piece->boundary) result.push_back({id.dim - 1, oriented ? tag : std::abs(tag)});
  return result;
}

}  // namespace geomesh::python
