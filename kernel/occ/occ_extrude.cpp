// The OpenCASCADE factory's extrusions: translations (prisms) and rotations (revolutions) of
// points, curves and surfaces, numbered as the reference numbers them.
#include <BRepOffsetAPI_MakePipe.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepSweep_Revol.hxx>
#include <BRep_Builder.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax1.hxx>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

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
  // New entities are numbered as the result holds them, highest dimension first.
  for (int dim = 3; dim >= 1; --dim)
    for (TopExp_Explorer it(result, kTypes[dim], dim < 3 ? kTypes[dim + 1] : TopAbs_SHAPE);
         it.More(); it.Next())
      shapes_->bindNew(dim, it.Current());
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
  return out;
}

}  // namespace geomesh
