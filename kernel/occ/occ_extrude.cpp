// The OpenCASCADE factory's extrusions: translations (prisms) and rotations (revolutions) of
// points, curves and surfaces, numbered as the reference numbers them.
#include <BRepOffsetAPI_MakePipe.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepSweep_Revol.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax1.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

namespace {

constexpr TopAbs_ShapeEnum kTypes[4] = {TopAbs_VERTEX, TopAbs_EDGE, TopAbs_FACE, TopAbs_SOLID};

// The sweep, whichever OpenCASCADE class makes it: its result and the history of each input.
struct Sweep {
  std::unique_ptr<BRepPrimAPI_MakePrism> prism;
  std::unique_ptr<BRepPrimAPI_MakeRevol> revolution;

  TopoDS_Shape result() { return prism ? prism->Shape() : revolution->Shape(); }
  TopoDS_Shape top(const TopoDS_Shape& s) {
    return prism ? prism->LastShape(s) : revolution->LastShape(s);
  }
  TopoDS_Shape generated(const TopoDS_Shape& s) {
    const TopTools_ListOfShape& list = prism ? prism->Generated(s) : revolution->Generated(s);
    if (!list.IsEmpty()) return list.First();
    if (!revolution) return {};
    // A whole turn leaves OpenCASCADE's history empty; the sweep itself still knows what each
    // input made, which counts when the result holds it (an edge on the axis makes nothing).
    const TopoDS_Shape made = const_cast<BRepSweep_Revol&>(revolution->Revol()).Shape(s);
    if (made.IsNull()) return {};
    if (resultParts.IsEmpty())
      for (TopAbs_ShapeEnum type : {TopAbs_EDGE, TopAbs_FACE, TopAbs_SOLID})
        TopExp::MapShapes(result(), type, resultParts);
    return resultParts.Contains(made) ? made : TopoDS_Shape();
  }

 private:
  TopTools_IndexedMapOfShape resultParts;  // filled on first need
};

void requireSweepable(const ExtrusionMotion& motion) {
  if (motion.kind == ExtrusionMotion::Kind::Normals)
    throw GeometryError("Extrude along normals (a boundary layer) is made by the built-in "
                        "kernel only: SetFactory(\"Built-in\") before it");
  if (motion.kind == ExtrusionMotion::Kind::Twist)
    throw GeometryError("Extrude: a twisted extrusion is not supported by the OpenCASCADE factory");
  if (motion.kind == ExtrusionMotion::Kind::Translation && norm(motion.translation) == 0)
    throw GeometryError("Extrude: the translation has zero length");
  if (motion.kind == ExtrusionMotion::Kind::Rotation &&
      (norm(motion.axis) == 0 || motion.angle == 0 || !std::isfinite(motion.angle)))
    throw GeometryError("Extrude: the rotation needs an axis and a non-zero angle");
}

Sweep sweep(const TopoDS_Shape& shapes, const ExtrusionMotion& motion) {
  Sweep s;
  if (motion.kind == ExtrusionMotion::Kind::Translation) {
    const Vec3 d = motion.translation;
    s.prism = std::make_unique<BRepPrimAPI_MakePrism>(shapes, gp_Vec(d.x, d.y, d.z), false);
    s.prism->Build();
    if (!s.prism->IsDone()) throw GeometryError("Extrude: OpenCASCADE could not sweep the shapes");
  } else {
    const Vec3 p = motion.axisPoint, a = motion.axis;
    const gp_Ax1 axis(gp_Pnt(p.x, p.y, p.z), gp_Dir(a.x, a.y, a.z));
    s.revolution = std::make_unique<BRepPrimAPI_MakeRevol>(shapes, axis, motion.angle, false);
    s.revolution->Build();
    if (!s.revolution->IsDone())
      throw GeometryError("Extrude: OpenCASCADE could not revolve the shapes");
  }
  return s;
}

// The boundary of an input whose images are the lateral entities: a curve's two ends, a
// surface's curves in the order the face stores them (each once).
std::vector<TopoDS_Shape> lateralSources(const OccShapes& shapes, EntityId e) {
  std::vector<TopoDS_Shape> out;
  if (e.dim == 1) {
    const TopoDS_Edge edge = TopoDS::Edge(shapes.find(1, e.tag).Oriented(TopAbs_FORWARD));
    out = {TopExp::FirstVertex(edge), TopExp::LastVertex(edge)};
  } else if (e.dim == 2) {
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(shapes.find(2, e.tag), TopAbs_EDGE, edges);
    for (int i = 1; i <= edges.Extent(); ++i) out.push_back(edges(i));
  }
  return out;
}

// A vertex the sweep made, not bound yet, and the input vertex it comes from (for a pipe: the
// one at its place), or null.
using MadeVertex = std::pair<TopoDS_Shape, TopoDS_Shape>;

// The vertices of `shape` not bound yet, each once.
std::vector<TopoDS_Shape> unboundVertices(const OccShapes& shapes, const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
  std::vector<TopoDS_Shape> out;
  for (int i = 1; i <= vertices.Extent(); ++i)
    if (!shapes.isBound(0, vertices(i))) out.push_back(vertices(i));
  return out;
}

// Once the made vertices are bound: each takes the mesh size of the vertex it comes from, and
// has none when that one has none (a size left under a reused tag by a removed point goes).
void copyMeshSizes(const OccShapes& shapes, const std::vector<MadeVertex>& made,
                   std::map<int, double>& sizes) {
  for (const auto& [vertex, source] : made) {
    if (!shapes.isBound(0, vertex)) continue;
    const int tag = shapes.tagOf(0, vertex);
    const auto size = source.IsNull() ? sizes.end() : sizes.find(shapes.tagOf(0, source));
    if (size != sizes.end())
      sizes[tag] = size->second;
    else
      sizes.erase(tag);
  }
}

// The input vertex at the place of `vertex` (to their tolerances), or null.
TopoDS_Shape coincidentVertex(const TopoDS_Vertex& vertex, const TopoDS_Shape& inputs) {
  const gp_Pnt at = BRep_Tool::Pnt(vertex);
  for (TopExp_Explorer it(inputs, TopAbs_VERTEX); it.More(); it.Next()) {
    const TopoDS_Vertex input = TopoDS::Vertex(it.Current());
    if (at.Distance(BRep_Tool::Pnt(input)) <=
        BRep_Tool::Tolerance(vertex) + BRep_Tool::Tolerance(input))
      return input;
  }
  return {};
}

}  // namespace

std::vector<EntityId> OccFactory::extrude(const std::vector<EntityId>& shapes,
                                          const ExtrusionMotion& motion,
                                          const ExtrusionLayers& layers) {
  requireSweepable(motion);
  TopoDS_Compound inputs;
  BRep_Builder builder;
  builder.MakeCompound(inputs);
  for (const EntityId& e : shapes) {
    if (e.dim < 0 || e.dim > 2)
      throw GeometryError("Extrude: " + entityName(e.dim, std::abs(e.tag)) + " cannot be extruded");
    builder.Add(inputs, shapes_->find(e.dim, std::abs(e.tag)));
  }
  Sweep s = guarded("Extrude", [&] { return sweep(inputs, motion); });
  const TopoDS_Shape result = guarded("Extrude", [&] { return s.result(); });
  // As in the reference, each point the sweep makes has the mesh size of the point it was
  // swept from (a point on the axis of a rotation makes none).
  std::vector<MadeVertex> made;
  for (TopExp_Explorer it(inputs, TopAbs_VERTEX); it.More(); it.Next()) {
    const TopoDS_Shape top = guarded("Extrude", [&] { return s.top(it.Current()); });
    if (!top.IsNull() && !shapes_->isBound(0, top)) made.push_back({top, it.Current()});
  }
  // New entities are numbered as the result holds them, highest dimension first.
  for (int dim = 3; dim >= 1; --dim)
    for (TopExp_Explorer it(result, kTypes[dim], dim < 3 ? kTypes[dim + 1] : TopAbs_SHAPE);
         it.More(); it.Next())
      shapes_->bindNew(dim, it.Current());
  copyMeshSizes(*shapes_, made, meshSizes_);
  auto tagOf = [&](int dim, const TopoDS_Shape& shape) {
    return shape.IsNull() ? 0 : shapes_->bindNew(dim, shape);
  };
  const auto motionRecord = std::make_shared<const ExtrusionMotion>(motion);
  std::vector<EntityId> out;
  for (const EntityId& e : shapes) {
    const int tag = std::abs(e.tag);
    const TopoDS_Shape& input = shapes_->find(e.dim, tag);
    const int top = tagOf(e.dim, guarded("Extrude", [&] { return s.top(input); }));
    const int body = tagOf(e.dim + 1, guarded("Extrude", [&] { return s.generated(input); }));
    out.push_back({e.dim, top});
    if (body == 0) continue;  // a point on the rotation axis sweeps nothing
    out.push_back({e.dim + 1, body});
    shapes_->extrusions[{e.dim + 1, body}] = ExtrusionRecord{tag, layers, top, motionRecord};
    for (const TopoDS_Shape& source : lateralSources(*shapes_, {e.dim, tag})) {
      const int lateral = tagOf(e.dim, guarded("Extrude", [&] { return s.generated(source); }));
      if (lateral == 0) continue;
      out.push_back({e.dim, lateral});
      const int sourceTag = shapes_->tagOf(e.dim - 1, source);
      const int lateralTop = tagOf(e.dim - 1, guarded("Extrude", [&] { return s.top(source); }));
      shapes_->extrusions[{e.dim, lateral}] =
          ExtrusionRecord{sourceTag, layers, lateralTop, motionRecord};
    }
  }
  return out;
}

// Extrude{shapes} Using Wire{w}: the shapes swept along the wire, its start first. Returns
// what the sweep made (the volumes of swept surfaces, the surfaces of swept curves), as the
// reference does.
std::vector<EntityId> OccFactory::extrudeAlongWire(const std::vector<EntityId>& shapes,
                                                   int wireTag) {
  const TopoDS_Wire spine = TopoDS::Wire(shapes_->findWire(std::abs(wireTag)));
  TopoDS_Compound inputs;
  BRep_Builder builder;
  builder.MakeCompound(inputs);
  int sweptDim = 1;
  for (const EntityId& e : shapes) {
    if (e.dim < 0 || e.dim > 2)
      throw GeometryError("Extrude: " + entityName(e.dim, std::abs(e.tag)) +
                          " cannot be swept along a wire");
    builder.Add(inputs, shapes_->find(e.dim, std::abs(e.tag)));
    sweptDim = std::max(sweptDim, e.dim + 1);
  }
  const TopoDS_Shape result = guarded("Extrude Using Wire", [&] {
    BRepOffsetAPI_MakePipe pipe(spine, inputs, GeomFill_IsDiscreteTrihedron);
    pipe.Build();
    if (!pipe.IsDone())
      throw GeometryError("Extrude Using Wire: OpenCASCADE could not sweep the shapes");
    return pipe.Shape();
  });
  // The reference gives a point the mesh size of a point at the same place: here, the copies
  // of the inputs' points at the start of the sweep have their sizes, the others none.
  std::vector<MadeVertex> made;
  for (const TopoDS_Shape& vertex : unboundVertices(*shapes_, result))
    made.push_back({vertex, coincidentVertex(TopoDS::Vertex(vertex), inputs)});
  // What the inputs made, the lowest dimension first as in the reference: a point's curve,
  // a curve's surface, a surface's volume.
  std::vector<EntityId> out;
  for (int dim = 1; dim <= sweptDim; ++dim) {
    TopExp_Explorer it = dim == 3 ? TopExp_Explorer(result, kTypes[3])
                                  : TopExp_Explorer(result, kTypes[dim], kTypes[dim + 1]);
    for (; it.More(); it.Next()) {
      const EntityId e{dim, shapes_->bindNew(dim, it.Current())};
      if (std::find(out.begin(), out.end(), e) == out.end()) out.push_back(e);
    }
  }
  copyMeshSizes(*shapes_, made, meshSizes_);
  return out;
}

}  // namespace geomesh
