// The OpenCASCADE factory's shapes and their tags; included only by kernel/occ/*.cpp.
#pragma once

#include <Standard_Failure.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopoDS_Shape.hxx>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kernel/model.h"

namespace geomesh {

// Every shape the factory knows, by dimension (0 vertices, 1 edges, 2 faces, 3 solids): tag ->
// shape, and shape -> tag (comparing shapes regardless of orientation). Curve loops (wires)
// and surface loops (shells) have tags of their own. As in Gmsh's OpenCASCADE kernel, a new
// tag is one more than the largest tag bound: removing the entity of the largest tag frees it.
struct OccShapes {
  std::map<int, TopoDS_Shape> byTag[4];
  TopTools_DataMapOfShapeInteger tags[4];
  std::map<int, TopoDS_Shape> wires;
  std::map<int, TopoDS_Shape> shells;
  // Extruded entities: how they were swept (forgotten when the entity goes).
  std::map<EntityId, ExtrusionRecord> extrusions;
  // Mesh constraints on entities: periodicity, embedded entities, compounds (forgotten when
  // the entity goes).
  struct Constraints {
    std::optional<Periodicity> periodic = std::nullopt;
    std::vector<int> embedded[3] = {};  // points, curves, surfaces inside the entity
    std::vector<int> compound = {};
  };
  std::map<EntityId, Constraints> constraints;

  bool isBound(int dim, const TopoDS_Shape& s) const { return tags[dim].IsBound(s); }
  bool contains(int dim, int tag) const {
    return dim >= 0 && dim <= 3 && byTag[dim].contains(tag);
  }
  int tagOf(int dim, const TopoDS_Shape& s) const { return tags[dim].Find(s); }
  int maxTag(int dim) const { return byTag[dim].empty() ? 0 : byTag[dim].rbegin()->first; }
  // The shape of (dim, tag); throws GeometryError ("Volume 3 is not defined") if unbound.
  const TopoDS_Shape& find(int dim, int tag) const;
  const TopoDS_Shape& findWire(int tag) const;
  const TopoDS_Shape& findShell(int tag) const;

  // Binds `s` (of dimension `dim`) under `tag`, then every sub-shape not bound yet, depth
  // first (each face, with each of its edges, with each of their vertices), under the next
  // free tags of their dimensions. A shape already bound keeps its tag.
  void bindTree(int dim, int tag, const TopoDS_Shape& s);
  // bindTree under the next free tag, or under its tag if `s` is bound already. Returns it.
  int bindNew(int dim, const TopoDS_Shape& s);
  // Binds `s` alone under `tag`; its sub-shapes are left to a later bindTree.
  void bindShape(int dim, int tag, const TopoDS_Shape& s) { bindOne(dim, tag, s); }
  // Forgets (dim, tag); recursive: also its sub-shapes that no other bound shape uses.
  void unbind(int dim, int tag, bool recursive);

 private:
  void bindOne(int dim, int tag, const TopoDS_Shape& s);
};

// Binds the shapes of `shape` (a compound, say) under new tags, as the reference binds what it
// reads: its solids, then the faces outside them, the edges outside those, the free vertices;
// allDimensions false: only the shapes of the highest dimension present. Returns the shapes
// of the highest dimension present, in that order.
std::vector<EntityId> bindShapes(OccShapes& shapes, const TopoDS_Shape& shape, bool allDimensions);

// Every bound shape that is not part of another one, as one compound.
TopoDS_Shape compoundOfAll(const OccShapes& shapes);
// The given entities' shapes as one compound, in their order (operations on them together
// keep the sub-shapes they share shared).
TopoDS_Shape compoundOf(const OccShapes& shapes, const std::vector<EntityId>& entities);

// Runs `build`, turning an OpenCASCADE failure into a GeometryError "what: reason".
template <class Build>
decltype(auto) guarded(const std::string& what, Build build);

// Puts the periodicity, embedding and compounds recorded on the shapes into the model's copies
// of their entities (kernel/occ/occ_constraints.cpp).
void applyConstraints(const OccShapes& shapes, Model& model);

// The dimension of a vertex, edge, face or solid; -1 for another kind of shape.
int shapeDimension(const TopoDS_Shape& s);
// "Point", "Curve", "Surface", "Volume".
const char* entityKind(int dim);
// "Volume 3".
std::string entityName(int dim, int tag);

[[noreturn]] void throwOccFailure(const std::string& what, const Standard_Failure& failure);

template <class Build>
decltype(auto) guarded(const std::string& what, Build build) {
  try {
    return build();
  } catch (const Standard_Failure& failure) {
    throwOccFailure(what, failure);
  }
}

}  // namespace geomesh
