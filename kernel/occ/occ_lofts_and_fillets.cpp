// The OpenCASCADE factory's lofts (ThruSections), fillets and chamfers of volumes.
#include <BRepBndLib.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepGProp.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

namespace {

// Binds the volumes of `result` (or its surfaces, when it has no volume), the first under
// `tag` when tag >= 0, the others under new tags. Returns them.
std::vector<EntityId> bindVolumes(OccShapes& shapes, const TopoDS_Shape& result, int tag) {
  std::vector<EntityId> out;
  for (int dim : {3, 2}) {
    for (TopExp_Explorer it(result, dim == 3 ? TopAbs_SOLID : TopAbs_FACE); it.More(); it.Next()) {
      if (tag >= 0 && out.empty() && !shapes.contains(dim, tag)) {
        shapes.bindTree(dim, tag, it.Current());
        out.push_back({dim, tag});
      } else {
        out.push_back({dim, shapes.bindNew(dim, it.Current())});
      }
    }
    if (!out.empty()) break;
  }
  return out;
}

// Whether two sections are the same curve in space (OpenCASCADE fails, and may crash, on a
// loft between coincident sections): the same length, centre of mass and bounding box.
bool coincident(const TopoDS_Wire& a, const TopoDS_Wire& b) {
  GProp_GProps pa, pb;
  BRepGProp::LinearProperties(a, pa);
  BRepGProp::LinearProperties(b, pb);
  Bnd_Box ba, bb;
  BRepBndLib::Add(a, ba);
  BRepBndLib::Add(b, bb);
  if (ba.IsVoid() || bb.IsVoid()) return false;
  const double size = std::max(ba.CornerMin().Distance(ba.CornerMax()), 1e-300);
  const double tolerance = std::max(1e-7, 1e-9 * size);
  return std::abs(pa.Mass() - pb.Mass()) < tolerance &&
         pa.CentreOfMass().Distance(pb.CentreOfMass()) < tolerance &&
         ba.CornerMin().Distance(bb.CornerMin()) < tolerance &&
         ba.CornerMax().Distance(bb.CornerMax()) < tolerance;
}

}  // namespace

std::vector<EntityId> OccFactory::addThruSections(int tag, const std::vector<int>& wires,
                                                  bool ruled, bool makeSolid) {
  const std::string what = std::string(ruled ? "Ruled ThruSections" : "ThruSections") +
                           (tag >= 0 ? " " + std::to_string(tag) : "");
  if (wires.size() < 2) throw GeometryError(what + " needs at least two curve loops or wires");
  if (tag >= 0 && shapes_->contains(makeSolid ? 3 : 2, tag))
    throw GeometryError(what + ": " + entityName(makeSolid ? 3 : 2, tag) + " already exists");
  for (std::size_t k = 1; k < wires.size(); ++k) {
    const TopoDS_Wire& a = TopoDS::Wire(shapes_->findWire(std::abs(wires[k - 1])));
    const TopoDS_Wire& b = TopoDS::Wire(shapes_->findWire(std::abs(wires[k])));
    if (coincident(a, b))
      throw GeometryError(what + ": sections " + std::to_string(std::abs(wires[k - 1])) +
                          " and " + std::to_string(std::abs(wires[k])) +
                          " coincide; a loft needs distinct consecutive sections");
  }
  const TopoDS_Shape result = guarded(what, [&] {
    BRepOffsetAPI_ThruSections loft(makeSolid, ruled);
    for (int w : wires) loft.AddWire(TopoDS::Wire(shapes_->findWire(std::abs(w))));
    loft.CheckCompatibility(false);
    loft.Build();
    if (!loft.IsDone()) throw GeometryError(what + ": OpenCASCADE could not loft these sections");
    return loft.Shape();
  });
  return bindVolumes(*shapes_, result, tag);
}

namespace {

// Builds, for each volume in turn, the shape `round` makes of it; the volumes go (with their
// sub-shapes that nothing else uses) and the results take new tags.
template <class Round>
std::vector<EntityId> replaceVolumes(OccShapes& shapes, const std::vector<int>& volumes,
                                     const std::string& what, Round round) {
  TopoDS_Compound results;
  BRep_Builder builder;
  builder.MakeCompound(results);
  for (int v : volumes)
    builder.Add(results, guarded(what, [&] { return round(shapes.find(3, v)); }));
  for (int v : volumes) shapes.unbind(3, v, true);
  std::vector<EntityId> out;
  for (TopExp_Explorer it(results, TopAbs_SOLID); it.More(); it.Next())
    out.push_back({3, shapes.bindNew(3, it.Current())});
  return out;
}

// "0.6", or "0.1, 0.2": the sizes given, as a script writes them.
std::string numberText(const std::vector<double>& values) {
  std::string text;
  for (double v : values) {
    std::ostringstream one;
    one << v;
    text += (text.empty() ? "" : ", ") + one.str();
  }
  return text;
}

// "curve 13", "curves 1, 2".
std::string curveList(const std::vector<int>& curves) {
  std::string text = curves.size() == 1 ? "curve " : "curves ";
  for (std::size_t i = 0; i < curves.size(); ++i)
    text += (i ? ", " : "") + std::to_string(std::abs(curves[i]));
  return text;
}

std::vector<TopoDS_Edge> edgesOf(const OccShapes& shapes, const TopoDS_Shape& volume,
                                 const std::vector<int>& curves) {
  std::vector<TopoDS_Edge> edges;
  for (int c : curves) {
    const TopoDS_Shape& edge = shapes.find(1, std::abs(c));
    for (TopExp_Explorer it(volume, TopAbs_EDGE); it.More(); it.Next())
      if (it.Current().IsSame(edge)) {
        edges.push_back(TopoDS::Edge(it.Current()));
        break;
      }
  }
  return edges;
}

}  // namespace

std::vector<EntityId> OccFactory::fillet(const std::vector<int>& volumes,
                                         const std::vector<int>& curves,
                                         const std::vector<double>& radii) {
  const std::string what = "Fillet";
  if (radii.empty() || (radii.size() != 1 && radii.size() != curves.size() &&
                        radii.size() != 2 * curves.size()))
    throw GeometryError(what + " takes one radius, one per curve, or two per curve");
  for (double r : radii)
    if (!(r > 0)) throw GeometryError(what + ": radii must be positive");
  return replaceVolumes(*shapes_, volumes, what, [&](const TopoDS_Shape& volume) {
    BRepFilletAPI_MakeFillet maker(volume);
    const std::vector<TopoDS_Edge> edges = edgesOf(*shapes_, volume, curves);
    if (edges.empty()) throw GeometryError(what + ": none of the curves bounds the volume");
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (radii.size() == 1) maker.Add(radii[0], edges[i]);
      else if (radii.size() == curves.size()) maker.Add(radii[i], edges[i]);
      else maker.Add(radii[2 * i], radii[2 * i + 1], edges[i]);
    }
    maker.Build();
    if (!maker.IsDone())
      throw GeometryError(what + ": radius " + numberText(radii) + " is too large for " +
                          curveList(curves) + " (OpenCASCADE could not round them)");
    return maker.Shape();
  });
}

std::vector<EntityId> OccFactory::chamfer(const std::vector<int>& volumes,
                                          const std::vector<int>& curves,
                                          const std::vector<int>& surfaces,
                                          const std::vector<double>& distances) {
  const std::string what = "Chamfer";
  if (distances.empty()) throw GeometryError(what + " needs a distance");
  for (double d : distances)
    if (!(d > 0)) throw GeometryError(what + ": distances must be positive");
  return replaceVolumes(*shapes_, volumes, what, [&](const TopoDS_Shape& volume) {
    BRepFilletAPI_MakeChamfer maker(volume);
    TopTools_IndexedDataMapOfShapeListOfShape facesOfEdge;
    TopExp::MapShapesAndAncestors(volume, TopAbs_EDGE, TopAbs_FACE, facesOfEdge);
    const std::vector<TopoDS_Edge> edges = edgesOf(*shapes_, volume, curves);
    if (edges.empty()) throw GeometryError(what + ": none of the curves bounds the volume");
    for (std::size_t i = 0; i < edges.size(); ++i) {
      // The face measuring the first distance: the one given, if it holds the curve.
      const TopTools_ListOfShape& faces = facesOfEdge.FindFromKey(edges[i]);
      TopoDS_Face face = TopoDS::Face(faces.First());
      if (i < surfaces.size() && shapes_->contains(2, std::abs(surfaces[i])))
        for (const TopoDS_Shape& f : faces)
          if (f.IsSame(shapes_->find(2, std::abs(surfaces[i])))) face = TopoDS::Face(f);
      const double d = distances[std::min(i, distances.size() - 1)];
      if (distances.size() == 2 * curves.size())
        maker.Add(distances[2 * i], distances[2 * i + 1], edges[i], face);
      else
        maker.Add(d, d, edges[i], face);
    }
    maker.Build();
    if (!maker.IsDone())
      throw GeometryError(what + ": distance " + numberText(distances) + " is too large for " +
                          curveList(curves) + " (OpenCASCADE could not bevel them)");
    return maker.Shape();
  });
}

}  // namespace geomesh
