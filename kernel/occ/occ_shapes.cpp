// Tag bookkeeping of the OpenCASCADE factory: binding shapes and their sub-shapes to tags.
#include "kernel/occ/occ_shapes.h"

#include <BRep_Builder.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>

#include <set>

#include "kernel/geometry_error.h"

namespace geomesh {

namespace {

constexpr TopAbs_ShapeEnum kShapeTypes[4] = {TopAbs_VERTEX, TopAbs_EDGE, TopAbs_FACE,
                                              TopAbs_SOLID};

}  // namespace

int shapeDimension(const TopoDS_Shape& s) {
  switch (s.ShapeType()) {
    case TopAbs_VERTEX: return 0;
    case TopAbs_EDGE: return 1;
    case TopAbs_FACE: return 2;
    case TopAbs_SOLID: return 3;
    default: return -1;
  }
}

const char* entityKind(int dim) {
  static constexpr const char* kNames[4] = {"Point", "Curve", "Surface", "Volume"};
  return dim >= 0 && dim <= 3 ? kNames[dim] : "Entity";
}

std::string entityName(int dim, int tag) {
  return std::string(entityKind(dim)) + " " + std::to_string(tag);
}

void throwOccFailure(const std::string& what, const Standard_Failure& failure) {
  const char* reason = failure.GetMessageString();
  throw GeometryError(what + ": " +
                      (reason && *reason ? reason : std::string("OpenCASCADE could not build it")) +
                      " (" + failure.DynamicType()->Name() + ")");
}

const TopoDS_Shape& OccShapes::find(int dim, int tag) const {
  if (!contains(dim, tag)) throw GeometryError(entityName(dim, tag) + " is not defined");
  return byTag[dim].at(tag);
}

const TopoDS_Shape& OccShapes::findWire(int tag) const {
  auto it = wires.find(tag);
  if (it == wires.end())
    throw GeometryError("Curve Loop " + std::to_string(tag) + " is not defined");
  return it->second;
}

const TopoDS_Shape& OccShapes::findShell(int tag) const {
  auto it = shells.find(tag);
  if (it == shells.end())
    throw GeometryError("Surface Loop " + std::to_string(tag) + " is not defined");
  return it->second;
}

void OccShapes::bindOne(int dim, int tag, const TopoDS_Shape& s) {
  byTag[dim][tag] = s;
  tags[dim].Bind(s, tag);
}

// Exploring each type in turn follows the same order as the depth-first walk: the explorer
// visits faces, then their wires' edges, then the edges' vertices, in the same nesting.
void OccShapes::bindTree(int dim, int tag, const TopoDS_Shape& s) {
  bindOne(dim, tag, s);
  for (int sub = dim - 1; sub >= 0; --sub)
    for (TopExp_Explorer it(s, kShapeTypes[sub]); it.More(); it.Next())
      if (!isBound(sub, it.Current())) bindOne(sub, maxTag(sub) + 1, it.Current());
}

int OccShapes::bindNew(int dim, const TopoDS_Shape& s) {
  const int tag = isBound(dim, s) ? tagOf(dim, s) : maxTag(dim) + 1;
  bindTree(dim, tag, s);
  return tag;
}

std::vector<EntityId> bindShapes(OccShapes& shapes, const TopoDS_Shape& shape,
                                 bool allDimensions) {
  std::vector<EntityId> top;
  std::set<EntityId> listed;
  for (int dim = 3; dim >= 0; --dim) {
    TopExp_Explorer it = dim == 3 ? TopExp_Explorer(shape, kShapeTypes[3])
                                  : TopExp_Explorer(shape, kShapeTypes[dim], kShapeTypes[dim + 1]);
    const bool first = top.empty();
    for (; it.More(); it.Next()) {
      const EntityId e{dim, shapes.bindNew(dim, it.Current())};
      if (first && listed.insert(e).second) top.push_back(e);
    }
    if (!top.empty() && !allDimensions) break;
  }
  return top;
}

TopoDS_Shape compoundOfAll(const OccShapes& shapes) {
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  TopTools_IndexedMapOfShape inside;
  for (int dim = 3; dim >= 0; --dim)
    for (const auto& [tag, shape] : shapes.byTag[dim]) {
      if (inside.Contains(shape)) continue;
      builder.Add(all, shape);
      for (int sub = dim - 1; sub >= 0; --sub) TopExp::MapShapes(shape, kShapeTypes[sub], inside);
    }
  return all;
}

TopoDS_Shape compoundOf(const OccShapes& shapes, const std::vector<EntityId>& entities) {
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (const EntityId& e : entities) builder.Add(all, shapes.find(e.dim, std::abs(e.tag)));
  return all;
}

void OccShapes::unbind(int dim, int tag, bool recursive) {
  auto found = byTag[dim].find(tag);
  if (found == byTag[dim].end()) return;
  const TopoDS_Shape shape = found->second;
  tags[dim].UnBind(shape);
  byTag[dim].erase(found);
  extrusions.erase({dim, tag});
  constraints.erase({dim, tag});
  if (!recursive) return;
  // From the highest dimension down: a sub-shape of `shape` stays when a shape still bound
  // (of a higher dimension) holds it.
  for (int sub = dim - 1; sub >= 0; --sub) {
    TopTools_IndexedMapOfShape used;
    for (int up = sub + 1; up <= 3; ++up)
      for (const auto& entry : byTag[up])
        TopExp::MapShapes(entry.second, kShapeTypes[sub], used);
    for (TopExp_Explorer it(shape, kShapeTypes[sub]); it.More(); it.Next())
      if (isBound(sub, it.Current()) && !used.Contains(it.Current())) {
        const int subTag = tagOf(sub, it.Current());
        tags[sub].UnBind(it.Current());
        byTag[sub].erase(subTag);
        extrusions.erase({sub, subTag});
        constraints.erase({sub, subTag});
      }
  }
}

}  // namespace geomesh
